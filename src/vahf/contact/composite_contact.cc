#include "vahf/contact/composite_contact.h"

#include <algorithm>

namespace vahf::contact {

CompositeContact::CompositeContact(std::vector<std::shared_ptr<const ContactModel>> parts)
    : parts_(std::move(parts)) {}

ContactForces CompositeContact::DoEvaluate(const RigidMotion& m,
                                           ContactCounters& counters,
                                           ContactJacobian* jacobian) const {
  ContactForces out;
  ContactJacobian part_jacobian;
  for (const auto& part : parts_) {
    const ContactForces f =
        part->Evaluate(m, &counters, jacobian ? &part_jacobian : nullptr);
    out.normal_force += f.normal_force;
    out.friction_force += f.friction_force;
    out.film_force += f.film_force;
    out.torque += f.torque;
    out.points_in_contact += f.points_in_contact;
    out.rim_points_in_contact += f.rim_points_in_contact;
    out.max_depth = std::max(out.max_depth, f.max_depth);
    if (jacobian) {
      jacobian->normal_force += part_jacobian.normal_force;
      jacobian->friction_force += part_jacobian.friction_force;
      jacobian->film_force += part_jacobian.film_force;
      jacobian->torque += part_jacobian.torque;
    }
  }
  if (!parts_.empty())
    counters.evaluations -= parts_.size() - 1;  // one evaluation of the whole
  return out;
}

}  // namespace vahf::contact
