// Several contact models of one moving part acting together, their loads,
// Jacobians and counters summed in a fixed order (a scene whose revolved
// pairs take the exact revolved contact and whose other pairs the general
// path: contact_registry.cc).
#pragma once

#include <memory>
#include <vector>

#include "vahf/contact/contact_model.h"

namespace vahf::contact {

class CompositeContact final : public ContactModel {
 public:
  explicit CompositeContact(std::vector<std::shared_ptr<const ContactModel>> parts);

  // Every part's points, in the parts' order; false when any part has none
  // to give.
  bool AddContactPoints(const RigidMotion& motion, double margin,
                        ContactCounters& counters,
                        std::vector<ContactPoint>* points) const override;
  // The parts' smooth loads summed in order.
  ContactForces SmoothLoads(const RigidMotion& motion, ContactCounters& counters,
                            ContactJacobian* jacobian) const override;

 protected:
  ContactForces DoEvaluate(const RigidMotion& motion, ContactCounters& counters,
                           ContactJacobian* jacobian) const override;

 private:
  std::vector<std::shared_ptr<const ContactModel>> parts_;
};

}  // namespace vahf::contact
