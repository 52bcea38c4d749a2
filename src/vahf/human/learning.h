// Learning over repetitions: the paper's "adapting process" (Sec. 5.2: the
// mean of an operator's ten real assemblies is clearly shorter than the
// first), which the paper's model does not have. Off by default: a repeated
// operator is then the same operator.
//
// The time factor of repetition n >= 1 is De Jong's learning curve,
//   L(n) = M + (1 - M) n^(-b),
// J. R. De Jong, "The effects of increasing skill on cycle time and its
// consequences for time standards", Ergonomics 1 (1957) 51-60: M is the
// incompressible share of the task that practice does not shorten. M = 0 is
// the power law of practice of A. Newell and P. S. Rosenbloom, "Mechanisms of
// skill acquisition and the law of practice", in J. R. Anderson (ed.),
// Cognitive Skills and Their Acquisition, Erlbaum 1981, pp. 1-55.
//
// Where it acts. The operator's force is an impedance F = kappa Psi (T' - T)
// - b v with b = 2 zeta sqrt(kappa Psi m) (docs/design.md decision 2), whose
// free reach toward a held target takes a time proportional to
// sqrt(m / (kappa Psi)). Multiplying the operator's gain by G(n) = L(n)^-2
// therefore shortens a free reach by exactly L(n): a practised operator moves
// the same way, faster. It acts where fatigue acts, on Psi in the force and
// torque laws (Eqs. 7-8 and the assembly torque), and nowhere else: Eq. 5's
// estimate, the work of Eq. 4 and the exhaustion rule keep Psi itself.
// Contact, the decision interval and the chance of success are not scaled,
// so a cycle's time follows L(n) only approximately; a calibration fits b
// (and M) through the simulation, not through L(n) alone.
#pragma once

#include <string>

namespace vahf::human {

struct LearningParams {
  // "none": every repetition is the first (the paper's model); "power_law":
  // M = 0; "de_jong": with the floor M below.
  std::string model = "none";
  // b. 0.322 = -log2(0.8) is the "80 % curve" (each doubling of the
  // repetitions takes 80 % of the time) of T. P. Wright, "Factors affecting
  // the cost of airplanes", J. Aeronaut. Sci. 3 (1936) 122-128, the customary
  // starting value for manual assembly; a calibration target.
  double exponent = 0.322;
  // M of De Jong's curve (model "de_jong" only), in [0, 1): the share of the
  // task practice cannot shorten, larger the more of it a machine (here the
  // part's physics) paces. De Jong's own values could not be read here; 0.25
  // is a starting value, not a cited one: a calibration target.
  double floor = 0.25;
};

// L(n): the share of its first repetition's time the n-th takes (n >= 1);
// 1 for every n when the model is "none".
double PracticeTimeFactor(const LearningParams& params, int repetition);

// G(n) = L(n)^-2: the factor on the operator's gain at repetition n.
double PracticeGain(const LearningParams& params, int repetition);

}  // namespace vahf::human
