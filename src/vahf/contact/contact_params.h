// The contact's parameters (docs/design.md decision 7). `ContactParams` holds
// what a scene sets for every model: the shared law, the shell, the
// penetration bound, the model's name, the oil, and `values` for the keys a
// model declares itself (ContactModelEntry::params, contact_registry.h).
// `PenaltyLaw` is the law the penalty family evaluates (point_load.h,
// penalty_contact.h, revolved_contact.h), filled by its builders.
#pragma once

#include <string>

#include "vahf/core/param_decl.h"

namespace vahf::contact {

// The law every model may read: normal stiffness and onset, dissipation,
// friction's regularisation.
struct ContactLaw {
  // Normal pressure per metre of penetration, Pa/m. Each shell point carries an
  // area, so the total stiffness of a face is stiffness * its area whatever the
  // shell density. 1e10 Pa/m keeps a 1 kg part resting on 1 cm^2 within
  // 0.1 micrometre, well under the 50 micrometre fits the scenes use.
  double stiffness = 1e10;
  // Depth over which the normal law blends in quadratically, m, so that the
  // force is C1 at contact onset.
  double onset_depth = 1e-6;
  // Hunt-Crossley dissipation, s/m: pressure scales by (1 + dissipation * rate
  // of penetration). K. H. Hunt and F. R. E. Crossley, J. Appl. Mech. 42 (1975).
  double dissipation = 0.5;
  // Slip speed below which Coulomb friction is regularised linearly, m/s.
  double friction_transition_speed = 1e-3;
};

// The law the penalty family evaluates: the shared law (the scene's, or the
// bound rule's stiffness) and what its builders add.
struct PenaltyLaw : ContactLaw {
  // The depth difference over which a load's direction blends across a
  // sharp edge's medial axis, m (kEdgeBlend, revolved_contact.h); 0: none.
  double edge_blend = 1e-6;
  // Line load per metre of penetration per metre of edge, Pa (kLineStiffness,
  // rim.h, or the bound rule's).
  double line_stiffness = 1e7;
  // Depth of the normal law's hardening barrier, m (contact_model.h); 0: none.
  // Not a scene parameter: with model "resolving" or "sampled" a trial sets it
  // just inside the penetration bound b (penetration_fraction times the
  // scene's smallest radial clearance), at b (1 - kBarrierMargin), so the
  // contact cannot pass the bound it is checked against; otherwise, and in a
  // scene without a radial fit, no barrier.
  double barrier_depth = 0.0;
};

struct ContactParams : ContactLaw {
  // Spacing of the point shell on the moving part's surface, m.
  double shell_spacing = 1e-3;
  // The penetration bound as a fraction of the scene's smallest radial
  // clearance: a contact deeper than this at an accepted step is a warning
  // (penetration_bound). 0.1: a penalty contact that resolves a fit must keep
  // its overlap an order of magnitude below the gap it resolves.
  double penetration_fraction = 0.1;
  // The contact model a trial builds (docs/physics.md, Contact):
  //   "shell" (the default): the moving part's point shell against the static
  //     parts' exact signed distances, stiffness as written, no rims, no
  //     barrier. Cheap, and it does not resolve a tight fit: a static edge
  //     sinks between shell points, a moving edge sits half a spacing outside
  //     the nearest shell point (the warnings record shows how deep).
  //   "resolving": the law that resolves a fit: when the scene has a radial fit,
  //     stiffnesses by the bound rule with the hardening barrier just inside
  //     the bound (barrier_depth):
  //     the largest steady load F = kappa |T_0 - T_t| + m g (the operator's
  //     Eq. 7 pull at the start plus the part's weight), carried by
  //     `rule_contact_length` of edge, sinks `rule_depth_fraction` of the
  //     bound b:
  //       line_stiffness = F / (l q b),  stiffness = line_stiffness / l,
  //     and impacts are the barrier's. For a fixed part that is, like the
  //     moving part, a solid of revolution, the exact rim arcs both ways
  //     (revolved_contact.h); for other pairs the sampled path below. Stiff:
  //     CVODE or CPodes integrates it.
  //   "sampled": resolving's law on sampled points for every pair, revolved
  //     or not: the moving part's point shell and rims against the static
  //     fields and the static parts' rims against the moving part's field
  //     (penalty_contact.h). The general path, and the reference the exact
  //     rim arcs are checked against.
  std::string model = "shell";
  // The values of the keys the models declare (contact_registry.h).
  core::ParamValues values;
  // Oiled fits (squeeze_film.h, docs/physics.md "Oiled fits"). The oil's
  // dynamic viscosity, Pa s; 0 (the default): dry. When it is above 0 every
  // contact of the part is lubricated: each thin annular gap between a
  // cylindrical face of the moving solid of revolution and a facing one of a
  // fixed solid of revolution holds a squeeze film, and the parts' Coulomb
  // coefficients give way to `lubricated_friction`. ISO VG 46 hydraulic oil
  // is 46 mm^2/s +- 10 % at 40 C (ISO 3448), 0.0397 Pa s at 862.9 kg/m^3;
  // about 0.085 Pa s at 25 C (ASTM D341 from 40 and 100 C; docs/physics.md).
  double lubricant_viscosity = 0.0;
  // The Coulomb coefficient of the parts' contact under the oil (boundary
  // lubrication). Hard steel on hard steel under a thin film of light
  // mineral oil: 0.1 sliding, 0.23 static (Kirk-Othmer Encyclopedia of
  // Chemical Technology, "Friction"; read in a secondary source only, so a
  // calibratable parameter).
  double lubricated_friction = 0.1;
  // The thinnest film the squeeze law admits, m: the smooth cap of its
  // eccentricity keeps the film's thinnest gap about this thick, below which
  // the surfaces' asperities share the load (mixed lubrication, film
  // parameter h / sigma below about 3) and the penalty contact acts. 1 um:
  // three times a composite roughness of 0.3 um; not measured for these
  // parts, a calibratable parameter.
  double film_floor = 1e-6;
  // Newton's coefficient of restitution of the parts' dry solids, for the
  // MoreauJean stepper's impact law (docs/physics.md, "Nonsmooth stepping";
  // the oil's part is the squeeze film's, not counted twice). Published
  // values for steel on steel lie between about 0.5 and 0.9, falling with
  // speed and with the parts' own vibration (W. Goldsmith, Impact, 1960,
  // Ch. 7); 0.5, the lower end for long parts whose impacts excite their own
  // bending, is an assumption of this harness, not a measurement of these
  // parts: a calibratable parameter. The compliant path's dissipation is its
  // own (Hunt-Crossley, `dissipation`).
  double restitution = 0.5;
};

}  // namespace vahf::contact
