#include "vahf/contact/contact_registry.h"

#include "vahf/contact/penalty_contact.h"
#include "vahf/core/error.h"

namespace vahf::contact {
namespace {

// The penalty contact of penalty_contact.h; with rims: both ways.
BuiltContact Penalty(const ContactSetup& s, const ContactParams& params, bool rims) {
  const auto rims_of = [&](const geometry::Shape& shape) {
    return rims ? MakeRims(shape, params.rim_spacing) : std::vector<RimPoint>{};
  };
  std::vector<Obstacle> obstacles;
  for (const ContactBody& f : s.fixed)
    obstacles.push_back({SignedDistance(*f.shape), f.pose, f.friction, f.bounding_radius,
                         rims_of(*f.shape)});
  std::vector<ShellPoint> shell = MakePointShell(*s.moving.shape, params.shell_spacing);
  BuiltContact out;
  out.shell_points = static_cast<std::int64_t>(shell.size());
  out.stiffness = params.stiffness;
  out.line_stiffness = rims ? params.line_stiffness : 0.0;
  out.model = std::make_shared<PenaltyContact>(
      std::move(shell), SignedDistance(*s.moving.shape), s.moving.bounding_radius,
      s.moving.friction, std::move(obstacles), params, rims_of(*s.moving.shape));
  return out;
}

BuiltContact Shell(const ContactSetup& s) { return Penalty(s, s.params, false); }

// docs/physics.md, Contact stiffness: the largest steady load F sinks a
// fraction q of the bound b over a short edge l,
//   line_stiffness = F / (l q b), stiffness = line_stiffness / l,
// and the hardening barrier stands at b. No radial fit: the scene's values.
BuiltContact Resolving(const ContactSetup& s) {
  ContactParams p = s.params;
  if (s.penetration_bound > 0) {
    p.barrier_depth = s.penetration_bound;  // the bound it is checked against
    const double l = p.rule_contact_length;
    p.line_stiffness = s.steady_load / (l * p.rule_depth_fraction * s.penetration_bound);
    p.stiffness = p.line_stiffness / l;
  }
  return Penalty(s, p, true);
}

}  // namespace

const std::vector<ContactModelEntry>& ContactModels() {
  static const std::vector<ContactModelEntry> models = {
      {"shell", "point shell vs static fields, given stiffness", Shell},
      {"resolving", "rims both ways, stiffness by the bound rule, barrier", Resolving},
  };
  return models;
}

std::vector<std::string> ContactModelNames() {
  std::vector<std::string> names;
  for (const ContactModelEntry& e : ContactModels()) names.emplace_back(e.name);
  return names;
}

BuiltContact BuildContact(const std::string& name, const ContactSetup& setup) {
  VAHF_CHECK(!setup.fixed.empty(), "a contact model needs a fixed part");
  for (const ContactModelEntry& e : ContactModels())
    if (name == e.name) return e.build(setup);
  VAHF_CHECK(false, "unknown contact model " + name + " passed validation");
  return {};
}

}  // namespace vahf::contact
