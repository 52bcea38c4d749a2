#include "vahf/contact/contact_registry.h"

#include <fmt/format.h>

#include <string_view>
#include <variant>

#include "vahf/contact/composite_contact.h"
#include "vahf/contact/penalty_contact.h"
#include "vahf/contact/point_load.h"
#include "vahf/contact/revolved_contact.h"
#include "vahf/contact/rim.h"
#include "vahf/contact/squeeze_film.h"
#include "vahf/core/error.h"

namespace vahf::contact {
namespace {

// l of the rule, m: 2 mm of edge, a short arc of a rim in line contact.
constexpr core::ParamDecl kRuleContactLength{
    "rule_contact_length",
    "m",
    core::ParamRule::kClosed,
    1e-4,
    10,
    2e-3,
    "edge length that carries the largest steady load (resolving, sampled)"};
// q of the rule: the steady load sinks a quarter of the bound, leaving the
// barrier's hardening to impacts.
constexpr core::ParamDecl kRuleDepthFraction{
    "rule_depth_fraction",
    "1",
    core::ParamRule::kOpenBelow,
    0,
    1,
    0.25,
    "share of the bound the largest steady load may sink (resolving, sampled)"};

// The penalty family's law from the scene's values; no barrier.
PenaltyLaw LawOf(const ContactParams& c) {
  PenaltyLaw law;
  static_cast<ContactLaw&>(law) = c;
  law.edge_blend = c.values.Get(kEdgeBlend);
  law.line_stiffness = c.values.Get(kLineStiffness);
  return law;
}

// The penalty contact of penalty_contact.h between the moving part and
// `fixed`; with rims: both ways.
BuiltContact Penalty(const ContactSetup& s, const std::vector<const ContactBody*>& fixed,
                     const PenaltyLaw& params, bool rims) {
  const double rim_spacing = s.params.values.Get(kRimSpacing);
  const auto rims_of = [&](const geometry::Shape& shape) {
    return rims ? MakeRims(shape, rim_spacing) : std::vector<RimPoint>{};
  };
  std::vector<Obstacle> obstacles;
  for (const ContactBody* f : fixed)
    obstacles.push_back({SignedDistance(*f->shape), f->pose, f->friction,
                         f->bounding_radius, rims_of(*f->shape)});
  std::vector<ShellPoint> shell = MakePointShell(*s.moving.shape, s.params.shell_spacing);
  BuiltContact out;
  out.shell_points = static_cast<std::int64_t>(shell.size());
  out.stiffness = params.stiffness;
  out.line_stiffness = rims ? params.line_stiffness : 0.0;
  out.barrier_depth = params.barrier_depth;
  out.model = std::make_shared<PenaltyContact>(
      std::move(shell), SignedDistance(*s.moving.shape), s.moving.bounding_radius,
      s.moving.friction, std::move(obstacles), params, rims_of(*s.moving.shape));
  return out;
}

std::vector<const ContactBody*> All(const ContactSetup& s) {
  std::vector<const ContactBody*> out;
  for (const ContactBody& f : s.fixed) out.push_back(&f);
  return out;
}

BuiltContact Shell(const ContactSetup& s) {
  return Penalty(s, All(s), LawOf(s.params), false);
}

// docs/physics.md, Contact stiffness: the largest steady load F sinks a
// fraction q of the bound b over a short edge l,
//   line_stiffness = F / (l q b), stiffness = line_stiffness / l,
// and the hardening barrier stands at b. No radial fit: the scene's values.
PenaltyLaw BoundRule(const ContactSetup& s) {
  PenaltyLaw p = LawOf(s.params);
  if (s.penetration_bound > 0) {
    p.barrier_depth = s.penetration_bound * (1.0 - kBarrierMargin);
    const double l = s.params.values.Get(kRuleContactLength);
    const double q = s.params.values.Get(kRuleDepthFraction);
    p.line_stiffness = s.steady_load / (l * q * s.penetration_bound);
    p.stiffness = p.line_stiffness / l;
  }
  return p;
}

const geometry::RevolvedProfile* ProfileOf(const ContactBody& b) {
  return std::get_if<geometry::RevolvedProfile>(b.shape);
}

// The bound rule's law on the general path for every pair: the moving shell
// and every part's rims, sampled, both ways.
BuiltContact Sampled(const ContactSetup& s) {
  return Penalty(s, All(s), BoundRule(s), true);
}

// The bound rule's law; the exact revolved contact (revolved_contact.h) for
// every fixed part that is, like the moving part, a solid of revolution, and
// the general path for the others.
BuiltContact Resolving(const ContactSetup& s) {
  const PenaltyLaw p = BoundRule(s);
  const geometry::RevolvedProfile* moving = ProfileOf(s.moving);
  std::vector<RevolvedContact::Solid> revolved;
  std::vector<const ContactBody*> general;
  for (const ContactBody& f : s.fixed) {
    const geometry::RevolvedProfile* profile = moving ? ProfileOf(f) : nullptr;
    if (profile)
      revolved.push_back(
          RevolvedContact::Make(*profile, f.pose, f.friction, f.bounding_radius));
    else
      general.push_back(&f);
  }
  if (revolved.empty()) return Penalty(s, general, p, true);
  BuiltContact out;
  out.stiffness = p.stiffness;
  out.line_stiffness = p.line_stiffness;
  out.barrier_depth = p.barrier_depth;
  out.model = std::make_shared<RevolvedContact>(
      RevolvedContact::Make(*moving, Eigen::Isometry3d::Identity(), s.moving.friction,
                            s.moving.bounding_radius),
      std::move(revolved), p);
  if (general.empty()) return out;
  BuiltContact rest = Penalty(s, general, p, true);
  out.shell_points = rest.shell_points;
  out.model = std::make_shared<CompositeContact>(
      std::vector<std::shared_ptr<const ContactModel>>{out.model, rest.model});
  return out;
}

}  // namespace

const std::vector<ContactModelEntry>& ContactModels() {
  static const std::vector<ContactModelEntry> models = {
      {"shell", "point shell vs static fields, given stiffness", Shell},
      {"resolving",
       "stiffness by the bound rule, barrier; exact rim arcs both ways for revolved "
       "pairs, sampled rims and shell for others",
       Resolving,
       {&kEdgeBlend, &kLineStiffness, &kRimSpacing, &kRuleContactLength,
        &kRuleDepthFraction},
       true},
      {"sampled",
       "resolving's law on sampled rims and shell for every pair (reference)",
       Sampled,
       {&kLineStiffness, &kRimSpacing, &kRuleContactLength, &kRuleDepthFraction},
       true},
  };
  return models;
}

const ContactModelEntry& FindContactModel(const std::string& name) {
  for (const ContactModelEntry& e : ContactModels())
    if (name == e.name) return e;
  VAHF_CHECK(false, "unknown contact model " + name + " passed validation");
  return ContactModels().front();
}

const std::vector<const core::ParamDecl*>& ContactModelParams() {
  static const std::vector<const core::ParamDecl*> params = [] {
    std::vector<const core::ParamDecl*> out;
    for (const ContactModelEntry& e : ContactModels())
      for (const core::ParamDecl* d : e.params) {
        bool seen = false;
        for (const core::ParamDecl* o : out) {
          VAHF_CHECK(o == d || std::string_view(o->key) != d->key,
                     std::string("contact parameter ") + d->key + " declared twice");
          seen = seen || o == d;
        }
        if (!seen) out.push_back(d);
      }
    return out;
  }();
  return params;
}

std::vector<std::string> ContactModelNames() {
  std::vector<std::string> names;
  for (const ContactModelEntry& e : ContactModels()) names.emplace_back(e.name);
  return names;
}

namespace {

// An oiled part (lubricant_viscosity > 0): the parts' Coulomb coefficients
// give way to the lubricated one, and the thin gaps between its cylindrical
// faces and the fixed solids of revolution hold squeeze films.
ContactSetup Lubricated(ContactSetup s) {
  s.moving.friction = s.params.lubricated_friction;
  for (ContactBody& f : s.fixed) f.friction = s.params.lubricated_friction;
  return s;
}

std::shared_ptr<const SqueezeFilm> Films(const ContactSetup& s) {
  const geometry::RevolvedProfile* moving = ProfileOf(s.moving);
  if (!moving) return nullptr;
  std::vector<FilmFace> faces;
  for (const ContactBody& f : s.fixed)
    if (const geometry::RevolvedProfile* fixed = ProfileOf(f)) {
      const std::vector<FilmFace> more = FilmFaces(*moving, *fixed, f.pose);
      faces.insert(faces.end(), more.begin(), more.end());
    }
  if (faces.empty()) return nullptr;
  // The law caps the film's eccentricity at 1 - floor / c: a floor at or
  // above a clearance leaves no film. InputError without a file: the trial
  // model that builds the contact names its scene.
  for (const FilmFace& f : faces)
    if (!(s.params.film_floor < f.clearance))
      throw InputError(
          "", "/parameters/contact/film_floor", fmt::format("{:g}", s.params.film_floor),
          fmt::format("below the radial clearance of every oiled fit ({:g} m "
                      "here)",
                      f.clearance));
  return std::make_shared<SqueezeFilm>(
      std::move(faces), FilmParams{s.params.lubricant_viscosity, s.params.film_floor});
}

}  // namespace

BuiltContact BuildContact(const std::string& name, const ContactSetup& setup) {
  VAHF_CHECK(!setup.fixed.empty(), "a contact model needs a fixed part");
  const bool oiled = setup.params.lubricant_viscosity > 0;
  const ContactSetup s = oiled ? Lubricated(setup) : setup;
  BuiltContact out = FindContactModel(name).build(s);
  if (oiled)
    if (auto film = Films(s))
      out.model = std::make_shared<CompositeContact>(
          std::vector<std::shared_ptr<const ContactModel>>{out.model, film});
  return out;
}

}  // namespace vahf::contact
