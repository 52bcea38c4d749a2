#include "vahf/contact/composite_contact.h"

#include <algorithm>
#include <memory>
#include <vector>

namespace vahf::contact {

CompositeContact::CompositeContact(std::vector<std::shared_ptr<const ContactModel>> parts)
    : parts_(std::move(parts)) {}

namespace {

// Adds part loads f (and their derivative pj) to out.
void Add(const ContactForces& f, const ContactJacobian* pj, ContactForces* out,
         ContactJacobian* jacobian) {
  out->normal_force += f.normal_force;
  out->friction_force += f.friction_force;
  out->film_force += f.film_force;
  out->torque += f.torque;
  out->points_in_contact += f.points_in_contact;
  out->rim_points_in_contact += f.rim_points_in_contact;
  out->max_depth = std::max(out->max_depth, f.max_depth);
  if (jacobian) {
    jacobian->normal_force += pj->normal_force;
    jacobian->friction_force += pj->friction_force;
    jacobian->film_force += pj->film_force;
    jacobian->torque += pj->torque;
  }
}

}  // namespace

bool CompositeContact::AddContactPoints(const RigidMotion& m, double margin,
                                        ContactCounters& counters,
                                        std::vector<ContactPoint>* points) const {
  for (const auto& part : parts_)
    if (!part->AddContactPoints(m, margin, counters, points)) return false;
  return true;
}

namespace {

// The parts' loads `of` each gives (its Jacobian zeroed first), summed in
// order.
template <typename Of>
ContactForces SumOf(const std::vector<std::shared_ptr<const ContactModel>>& parts,
                    ContactJacobian* jacobian, Of of) {
  ContactForces out;
  ContactJacobian part_jacobian;
  for (const auto& part : parts) {
    if (jacobian) part_jacobian = ContactJacobian{};
    Add(of(*part, jacobian ? &part_jacobian : nullptr), &part_jacobian, &out, jacobian);
  }
  return out;
}

}  // namespace

ContactForces CompositeContact::SmoothLoads(const RigidMotion& m,
                                            ContactCounters& counters,
                                            ContactJacobian* jacobian) const {
  return SumOf(parts_, jacobian, [&](const ContactModel& part, ContactJacobian* j) {
    return part.SmoothLoads(m, counters, j);
  });
}

ContactForces CompositeContact::DoEvaluate(const RigidMotion& m,
                                           ContactCounters& counters,
                                           ContactJacobian* jacobian) const {
  const ContactForces out =
      SumOf(parts_, jacobian, [&](const ContactModel& part, ContactJacobian* j) {
        return part.Evaluate(m, &counters, j);
      });
  if (!parts_.empty())
    counters.evaluations -= parts_.size() - 1;  // one evaluation of the whole
  return out;
}

}  // namespace vahf::contact
