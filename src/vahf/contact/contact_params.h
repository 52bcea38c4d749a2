// Parameters of the penalty contact between the moving part and the static
// parts (docs/design.md decision 7). The force law itself lands with the physics.
#pragma once

namespace vahf::contact {

struct ContactParams {
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
  // Spacing of the point shell on the moving part's surface, m.
  double shell_spacing = 1e-3;
  // The penetration bound as a fraction of the scene's smallest radial
  // clearance: a contact deeper than this at an accepted step is a warning
  // (penetration_bound). 0.1: a penalty contact that resolves a fit must keep
  // its overlap an order of magnitude below the gap it resolves.
  double penetration_fraction = 0.1;
};

}  // namespace vahf::contact
