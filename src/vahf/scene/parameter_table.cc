#include "vahf/scene/parameter_table.h"

#include <fmt/format.h>

#include <cstdint>
#include <string_view>
#include <utility>

#include "vahf/contact/contact_registry.h"
#include "vahf/core/error.h"
#include "vahf/scene/stepper_catalogue.h"

namespace vahf::scene {

std::string RuleText(const ParamSpec& s) {
  const std::string lo = NumberText(s.lo), hi = NumberText(s.hi);  // json_reader.h
  switch (s.rule) {
    case ParamRule::kClosed:
      return fmt::format("in [{}, {}]", lo, hi);
    case ParamRule::kOpenBelow:
      return fmt::format("in ({}, {}]", lo, hi);
    case ParamRule::kCount:
      return fmt::format("integer in [{}, {}]", static_cast<std::int64_t>(s.lo),
                         static_cast<std::int64_t>(s.hi));
    case ParamRule::kChoice: {
      std::string names;
      for (const auto& c : s.choices) names += (names.empty() ? "" : ", ") + c;
      return names;
    }
  }
  return "";
}

namespace {

// "name: description; ..." of a registry's entries, for the meaning of its choice.
template <class Entries>
std::string NamesAndDescriptions(const Entries& entries) {
  std::string text;
  for (const auto& e : entries)
    text += fmt::format("{}{}: {}", text.empty() ? "" : "; ", e.name, e.description);
  return text;
}

const std::string& ContactModelHelp() {
  static const std::string help = NamesAndDescriptions(contact::ContactModels());
  return help;
}

const std::string& StepperHelp() {
  static const std::string help = NamesAndDescriptions(StepperCatalogue());
  return help;
}

#define VAHF_REAL(field) [](Parameters& p) -> double& { return p.field; }
#define VAHF_COUNT(field) [](Parameters& p) -> int& { return p.field; }
#define VAHF_TEXT(field) [](Parameters& p) -> std::string& { return p.field; }

// Every number has a finite range: rules that match the numerics. The ranges are wide,
// orders of magnitude around any physical value, and exist so that no accepted value
// overflows the model's arithmetic or stalls its integration; where a bound has a
// source, it says so. Each function below holds one concept's rows, in table order.

// The human factor curves f, g and r (Sec. 3.2, Figs. 3-5).
std::vector<ParamSpec> SightGlanceReach() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"sight", "value_at_0", "1", R::kClosed, 0, 1, "f at Ang = 0 deg (Fig. 3)",
       VAHF_REAL(sight.value_at_0)},
      {"sight", "plateau_from_deg", "deg", R::kClosed, 0, 180,
       "f = 1 from this Ang (Sec. 3.2.1: 30)", VAHF_REAL(sight.plateau_from_deg)},
      {"sight", "plateau_to_deg", "deg", R::kClosed, 0, 180,
       "f = 1 up to this Ang (Sec. 3.2.1: 45)", VAHF_REAL(sight.plateau_to_deg)},
      {"sight", "value_at_180", "1", R::kClosed, 0, 1, "f at Ang = 180 deg",
       VAHF_REAL(sight.value_at_180)},
      {"glance", "value_at_0", "1", R::kClosed, 0, 1,
       "g at Anp = 0 deg (looking straight down, Fig. 5)", VAHF_REAL(glance.value_at_0)},
      {"glance", "plateau_from_deg", "deg", R::kClosed, 0, 180,
       "g = 1 from this Anp (Sec. 3.2.2: 30)", VAHF_REAL(glance.plateau_from_deg)},
      {"glance", "plateau_to_deg", "deg", R::kClosed, 0, 180,
       "g = 1 up to this Anp (Sec. 3.2.2: 90)", VAHF_REAL(glance.plateau_to_deg)},
      {"glance", "value_at_180", "1", R::kClosed, 0, 1,
       "g at Anp = 180 deg (looking straight up)", VAHF_REAL(glance.value_at_180)},
      // A reach breakpoint past twice the arm or the stature is a unit mistake.
      {"reach", "d1_arm_fraction", "1", R::kOpenBelow, 0, 2,
       "D1 = this * arm length (Sec. 3.2.2: 0.85)", VAHF_REAL(reach.d1_arm_fraction)},
      {"reach", "d2_height_fraction", "1", R::kOpenBelow, 0, 2,
       "D2 = this * height (Sec. 3.2.2: 0.39)", VAHF_REAL(reach.d2_height_fraction)},
      {"reach", "d3_height_fraction", "1", R::kOpenBelow, 0, 2,
       "D3 = this * height (Sec. 3.2.2: 0.68)", VAHF_REAL(reach.d3_height_fraction)},
      {"reach", "value_at_d2", "1", R::kClosed, 0, 1,
       "r at D2 (Fig. 4); r = 1 up to D1, 0 at D3", VAHF_REAL(reach.value_at_d2)},
  };
  return rows;
}

// Fatigue: A by Eq. 4 and Psi_c by Eq. 6.
std::vector<ParamSpec> Fatigue() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"fatigue", "k", "1", R::kOpenBelow, 0, 1e3, "K of Eq. 4 (Sec. 3.2.3: 6)",
       VAHF_REAL(fatigue.k)},
      // Eq. 6's 1600 kcal is 6.69e6 J; 1e10 J leaves three orders above it.
      {"fatigue", "a_max", "J", R::kOpenBelow, 0, 1e10,
       "A at which Psi_c = 0 (Eq. 6: 1600 kcal)", VAHF_REAL(fatigue.a_max)},
      {"fatigue", "psi_floor", "1", R::kClosed, 0, 1,
       "Psi_c at or below which the operator is exhausted", VAHF_REAL(fatigue.psi_floor)},
  };
  return rows;
}

// Learning over repetitions (human/learning.h): De Jong's curve on the
// operator's gain.
std::vector<ParamSpec> Learning() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"learning",
       "model",
       "-",
       R::kChoice,
       0,
       0,
       "none: every repetition is the first; power_law: L(n) = n^-b (Newell and "
       "Rosenbloom 1981); de_jong: L(n) = M + (1 - M) n^-b (De Jong 1957)",
       nullptr,
       nullptr,
       VAHF_TEXT(learning.model),
       {"none", "power_law", "de_jong"}},
      // An exponent of 5 halves the time by the second repetition 30-fold:
      // far past any practice curve (Wright's 80 % curve is 0.32).
      {"learning", "exponent", "1", R::kClosed, 0, 5,
       "b of L(n): repetition n takes L(n) of the first's time (80 % curve: 0.322)",
       VAHF_REAL(learning.exponent)},
      {"learning", "floor", "1", R::kClosed, 0, 0.99,
       "M of De Jong's L(n): the share practice cannot shorten",
       VAHF_REAL(learning.floor)},
  };
  return rows;
}

// The operator's force: Eq. 7's coefficient and its impedance
// (docs/design.md decision 2).
std::vector<ParamSpec> OperatorForce() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"guidance", "kappa", "N/m", R::kOpenBelow, 0, 1e6,
       "assembly force coefficient kappa (Eqs. 7, 8)", VAHF_REAL(guidance.kappa)},
      {"guidance",
       "mode",
       "-",
       R::kChoice,
       0,
       0,
       "operator: assembly force and torque act; none: they do not",
       nullptr,
       nullptr,
       VAHF_TEXT(guidance.mode),
       {"operator", "none"}},
      {"guidance", "damping_ratio", "1", R::kClosed, 0, 100,
       "damping of the force impedance, fraction of critical",
       VAHF_REAL(guidance.damping_ratio)},
      {"guidance", "weight_support", "1", R::kClosed, 0, 1,
       "fraction of the weight the operator carries in free motion",
       VAHF_REAL(guidance.weight_support)},
      // Hand and forearm are about 2.2 % of body mass (Winter, Biomechanics and
      // Motor Control of Human Movement, 4th ed., 2009, Table 4.1): under 3 kg.
      {"guidance", "hand_mass", "kg", R::kClosed, 0, 20,
       "hand and forearm mass moving with the grasped part",
       VAHF_REAL(guidance.hand_mass)},
  };
  return rows;
}

// The assembly torque and where the operator's force acts (docs/design.md
// decision 3).
std::vector<ParamSpec> TorqueAndGrasp() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"guidance", "torque_frequency", "rad/s", R::kOpenBelow, 0, 1e4,
       "natural frequency of the assembly torque impedance",
       VAHF_REAL(guidance.torque_frequency)},
      {"guidance", "torque_damping_ratio", "1", R::kClosed, 0, 100,
       "damping of the torque impedance, fraction of critical",
       VAHF_REAL(guidance.torque_damping_ratio)},
      {"guidance",
       "torque_law",
       "-",
       R::kChoice,
       0,
       0,
       "inertial: tau = I (Psi w^2 theta - 2 zeta w omega); wrist: tau = Psi K theta - "
       "B omega",
       nullptr,
       nullptr,
       VAHF_TEXT(guidance.torque_law),
       {"inertial", "wrist"}},
      // Passive wrist 0.5-3 N m/rad, co-contracted about 10 and more
      // (assembly_force.h); 100 N m/rad bounds what a hand can hold.
      {"guidance", "wrist_stiffness", "N m/rad", R::kOpenBelow, 0, 100,
       "K of the wrist torque law", VAHF_REAL(guidance.wrist_stiffness)},
      {"guidance", "wrist_damping", "N m s/rad", R::kClosed, 0, 100,
       "B of the wrist torque law", VAHF_REAL(guidance.wrist_damping)},
      {"guidance",
       "compliance_centre",
       "-",
       R::kChoice,
       0,
       0,
       "where the operator's force acts in contact: grasp, or leading_end (a remote "
       "centre compliance)",
       nullptr,
       nullptr,
       VAHF_TEXT(guidance.compliance_centre),
       {"grasp", "leading_end"}},
      {"guidance", "torque_sigma_deg", "deg", R::kClosed, 0, 180,
       "error of the held orientation per axis at eta = 1",
       VAHF_REAL(guidance.torque_sigma_deg)},
  };
  return rows;
}

// The operator in contact: Eq. 7 passing into Eq. 8.
std::vector<ParamSpec> ForceInContact() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"guidance", "contact_blend", "1", R::kClosed, 1e-3, 1e3,
       "contact normal force, in part weights, over which Eq. 7 passes into Eq. 8",
       VAHF_REAL(guidance.contact_blend)},
      {"guidance", "max_push", "N", R::kClosed, 0, 1e5,
       "largest push the operator adds to overcome friction (Eq. 8); 0: unbounded, the "
       "paper's",
       VAHF_REAL(guidance.max_push)},
      // A simple reaction, 240 ms (Card, Moran and Newell 1983; assembly_force.h).
      {"guidance", "stall_time", "s", R::kClosed, 0, 1e5,
       "a part resting in contact this long is withdrawn and guided in again (0.24: a "
       "simple reaction); 0: never",
       VAHF_REAL(guidance.stall_time)},
      {"guidance", "withdraw_distance", "m", R::kClosed, 0, 1,
       "how far the operator pulls a stopped part back (a named assumption)",
       VAHF_REAL(guidance.withdraw_distance)},
  };
  return rows;
}

// The vision error E_i of Eq. 5 (docs/design.md decision 4).
std::vector<ParamSpec> VisionError() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"guidance", "vision_sigma_depth", "m", R::kClosed, 0, 10,
       "E_i scale along the sight line at eta = 1 (Eq. 5)",
       VAHF_REAL(guidance.vision_sigma_depth)},
      {"guidance", "vision_sigma_lateral", "m", R::kClosed, 0, 10,
       "E_i scale across the sight line at eta = 1",
       VAHF_REAL(guidance.vision_sigma_lateral)},
  };
  return rows;
}

// The row of a declared key of `group`, read into the ParamValues `values`
// returns: a contact model's (ContactParams::values, contact_registry.h) or a
// stepper's (SimulationParams::stepper_values, steppers.def).
ParamSpec DeclaredRow(const char* group, const core::ParamDecl* d,
                      core::ParamValues& (*values)(Parameters&)) {
  return {
      group,      d->key,
      d->unit,    d->rule,
      d->lo,      d->hi,
      d->meaning, [d, values](Parameters& p) -> double& { return values(p).Upd(*d); }};
}

ParamSpec ModelRow(const core::ParamDecl* d) {
  return DeclaredRow(
      "contact", d, [](Parameters& p) -> core::ParamValues& { return p.contact.values; });
}

// The declared keys that keep the places they had among the shared rows
// before the models declared them; a model's other keys follow the contact
// model's rows.
constexpr const char* kPlacedModelKeys[] = {"edge_blend", "line_stiffness", "rim_spacing",
                                            "rule_contact_length", "rule_depth_fraction"};

bool Placed(const char* key) {
  for (const char* placed : kPlacedModelKeys)
    if (std::string_view(placed) == key) return true;
  return false;
}

ParamSpec ModelRow(const char* key) {
  VAHF_CHECK(Placed(key), std::string("contact parameter ") + key + " is not placed");
  for (const core::ParamDecl* d : contact::ContactModelParams())
    if (std::string_view(d->key) == key) return ModelRow(d);
  VAHF_CHECK(false, std::string("no contact model declares ") + key);
  return {};
}

// The contact's normal law, dissipation and friction (docs/design.md decision 7).
std::vector<ParamSpec> ContactLaw() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"contact", "stiffness", "Pa/m", R::kClosed, 1, 1e13,
       "normal pressure per metre of penetration", VAHF_REAL(contact.stiffness)},
      {"contact", "onset_depth", "m", R::kClosed, 1e-9, 1e-2,
       "depth of the C1 quadratic onset of the normal law",
       VAHF_REAL(contact.onset_depth)},
      ModelRow("edge_blend"),
      {"contact", "dissipation", "s/m", R::kClosed, 0, 1e3, "Hunt-Crossley dissipation",
       VAHF_REAL(contact.dissipation)},
      {"contact", "friction_transition_speed", "m/s", R::kClosed, 1e-6, 1,
       "slip speed of the regularised Coulomb law",
       VAHF_REAL(contact.friction_transition_speed)},
  };
  return rows;
}

// The contact model, its shell and rims, the penetration bound and the
// steady-load rule of the resolving models; then any other key a model
// declares.
std::vector<ParamSpec> ContactModelAndShells() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"contact", "shell_spacing", "m", R::kClosed, 1e-5, 1,
       "point spacing of the moving part's contact shell (at most 1e6 points: see scene "
       "rules)",
       VAHF_REAL(contact.shell_spacing)},
      ModelRow("line_stiffness"),
      ModelRow("rim_spacing"),
      {"contact", "penetration_fraction", "1", R::kOpenBelow, 0, 10,
       "penetration bound as a fraction of the smallest radial clearance (a warning past "
       "it)",
       VAHF_REAL(contact.penetration_fraction)},
      {"contact", "model", "-", R::kChoice, 0, 0, ContactModelHelp().c_str(), nullptr,
       nullptr, VAHF_TEXT(contact.model), contact::ContactModelNames()},
      ModelRow("rule_contact_length"),
      ModelRow("rule_depth_fraction"),
  };
  for (const core::ParamDecl* d : contact::ContactModelParams())
    if (!Placed(d->key)) rows.push_back(ModelRow(d));
  return rows;
}

// The oil in the fits: squeeze film and lubricated friction.
std::vector<ParamSpec> Lubrication() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"contact", "lubricant_viscosity", "Pa s", R::kClosed, 0, 10,
       "dynamic viscosity of the oil in the fits; 0: dry (squeeze film, lubricated "
       "friction)",
       VAHF_REAL(contact.lubricant_viscosity)},
      {"contact", "lubricated_friction", "1", R::kClosed, 0, 2,
       "Coulomb coefficient of the parts' contact under the oil",
       VAHF_REAL(contact.lubricated_friction)},
      {"contact", "film_floor", "m", R::kClosed, 1e-9, 1e-3,
       "thinnest oil film the squeeze law admits (smooth cap of the eccentricity)",
       VAHF_REAL(contact.film_floor)},
      {"contact", "restitution", "1", R::kClosed, 0, 1,
       "Newton's restitution of the dry solids at an impact (MoreauJean)",
       VAHF_REAL(contact.restitution)},
  };
  return rows;
}

// V (Eq. 1): ray cast, given or off.
std::vector<ParamSpec> Visibility() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"visibility",
       "mode",
       "-",
       R::kChoice,
       0,
       0,
       "raycast (Eq. 1), constant, or off (V = 1)",
       nullptr,
       nullptr,
       VAHF_TEXT(visibility.mode),
       {"raycast", "constant", "off"}},
      {"visibility", "value", "1", R::kClosed, 0, 1, "V when mode is constant",
       VAHF_REAL(visibility.value)},
      {"visibility", "grid", "rays", R::kCount, 1, visibility::kMaxGrid,
       "N of the N x N ray grid", nullptr, VAHF_COUNT(visibility.grid)},
      {"visibility", "tessellation_tolerance", "m", R::kClosed, 1e-6, 0.1,
       "chord error of part meshes", VAHF_REAL(visibility.tessellation_tolerance)},
  };
  return rows;
}

// The operator's decision instants and the outcomes decided at them
// (docs/design.md decisions 1 and 8).
std::vector<ParamSpec> DecisionsAndOutcomes() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      // 1 ms to 10 s: the range the stability suite spans; the paper's
      // operator decides about every 0.1 s (parameters.h).
      {"simulation", "decision_interval", "s", R::kClosed, 1e-3, 10,
       "time between the operator's decisions", VAHF_REAL(simulation.decision_interval)},
      {"simulation", "time_limit", "s", R::kOpenBelow, 0, 1e5,
       "a trial still running then ends as timeout", VAHF_REAL(simulation.time_limit)},
      {"simulation", "completion_distance", "m", R::kClosed, 1e-7, 1,
       "d_th: complete when |T - T_t| is below it (Sec. 3.1)",
       VAHF_REAL(simulation.completion_distance)},
      {"simulation", "completion_angle_deg", "deg", R::kOpenBelow, 0, 180,
       "and the angle to the target orientation is below it",
       VAHF_REAL(simulation.completion_angle_deg)},
      {"simulation", "jam_time", "s", R::kClosed, 1e-3, 1e5,
       "in contact this long without progress: jammed", VAHF_REAL(simulation.jam_time)},
      {"simulation", "jam_progress", "m", R::kClosed, 1e-9, 1,
       "approach to the target that counts as progress",
       VAHF_REAL(simulation.jam_progress)},
      // 0 counts no rest; 1 m/s is a hand's brisk motion, not a rest.
      {"simulation", "rest_speed", "m/s", R::kClosed, 0, 1,
       "in contact, nearing or leaving the target slower than this: resting",
       VAHF_REAL(simulation.rest_speed)},
      {"simulation", "rest_time", "s", R::kClosed, 1e-3, 1e5,
       "a rest this long or longer is counted (warning rest, the trial's rests)",
       VAHF_REAL(simulation.rest_time)},
      {"simulation", "divergence_speed", "m/s", R::kClosed, 1e-3, 1e5,
       "a part point faster than this: the integration diverged (numerical_failure)",
       VAHF_REAL(simulation.divergence_speed)},
  };
  return rows;
}

// The integrator and its settings (docs/design.md decision 11): the shared
// ones, then each stepper's own (steppers.def).
std::vector<ParamSpec> Integration() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"simulation", "integrator", "-", R::kChoice, 0, 0, StepperHelp().c_str(), nullptr,
       nullptr, VAHF_TEXT(simulation.integrator), StepperNames()},
      // Simbody's Integrator::setAccuracy asserts 0 < accuracy < 1; below
      // 1e-12 a relative error test nears the rounding of double (2.2e-16)
      // times the state's size and the step size collapses.
      {"simulation", "accuracy", "1", R::kClosed, 1e-12, 0.5,
       "integrator relative accuracy", VAHF_REAL(simulation.accuracy)},
  };
  for (const core::ParamDecl* d : StepperSettings())
    rows.push_back(DeclaredRow("simulation", d, [](Parameters& p) -> core::ParamValues& {
      return p.simulation.stepper_values;
    }));
  return rows;
}

// The check of every accepted step's size and the trial's work budget
// (docs/design.md decision 12).
std::vector<ParamSpec> StepChecksAndBudget() {
  using R = ParamRule;
  std::vector<ParamSpec> rows = {
      {"simulation", "step_floor", "s", R::kClosed, 1e-15, 1,
       "an accepted step shorter than this is a warning",
       VAHF_REAL(simulation.step_floor)},
      {"simulation", "max_steps", "steps", R::kCount, 1, 1e9,
       "work budget: a trial still running after this many accepted steps ends as "
       "step_budget",
       nullptr, VAHF_COUNT(simulation.max_steps)},
      {"simulation", "max_contact_tests", "tests", R::kClosed, 1, 1e15,
       "work budget: a trial still running after this many contact tests (point and rim "
       "queries and the profile edges they examine) ends as step_budget",
       VAHF_REAL(simulation.max_contact_tests)},
  };
  return rows;
}

std::vector<ParamSpec> MakeTable() {
  std::vector<ParamSpec> t;
  for (std::vector<ParamSpec> (*rows)() :
       {SightGlanceReach, Fatigue, Learning, OperatorForce, TorqueAndGrasp,
        ForceInContact, VisionError, ContactLaw, ContactModelAndShells, Lubrication,
        Visibility, DecisionsAndOutcomes, Integration, StepChecksAndBudget})
    for (ParamSpec& s : rows()) t.push_back(std::move(s));
  return t;
}

#undef VAHF_REAL
#undef VAHF_COUNT
#undef VAHF_TEXT

}  // namespace

const std::vector<ParamSpec>& ParameterTable() {
  static const std::vector<ParamSpec> table = MakeTable();
  return table;
}

std::string ParamName(const ParamSpec& spec) {
  return std::string(spec.group) + "/" + spec.key;
}

std::vector<std::string> ParamNames() {
  std::vector<std::string> names;
  for (const ParamSpec& s : ParameterTable()) names.push_back(ParamName(s));
  return names;
}

const ParamSpec* FindParam(const std::string& name) {
  for (const ParamSpec& s : ParameterTable())
    if (ParamName(s) == name) return &s;
  return nullptr;
}

void ReadParamValue(const ParamSpec& s, const JsonNode& v, Parameters* p) {
  switch (s.rule) {
    case ParamRule::kClosed:
      s.real(*p) = v.InRange(s.lo, s.hi);
      break;
    case ParamRule::kOpenBelow:
      s.real(*p) = v.InOpenClosed(s.lo, s.hi);
      break;
    case ParamRule::kCount: {
      const std::int64_t n =
          v.Integer(static_cast<std::int64_t>(s.lo), static_cast<std::int64_t>(s.hi));
      if (s.count)
        s.count(*p) = static_cast<int>(n);
      else
        s.real(*p) = static_cast<double>(n);  // a declared count (ParamValues::Count)
      break;
    }
    case ParamRule::kChoice:
      s.text(*p) = v.Choice(s.choices);
      break;
  }
}

std::string ParamValueText(const ParamSpec& spec, const Parameters& p) {
  Parameters q = p;  // the accessors are the loader's, which writes through them
  if (spec.real && spec.rule == ParamRule::kCount)
    return fmt::format("{}", static_cast<std::int64_t>(spec.real(q)));
  if (spec.real) return fmt::format("{}", spec.real(q));
  if (spec.count) return fmt::format("{}", spec.count(q));
  return spec.text(q);
}

std::string ParameterTableMarkdown() {
  const Parameters defaults;
  std::string out =
      "| parameter | unit | rule | default | meaning |\n"
      "| --- | --- | --- | --- | --- |\n";
  for (const ParamSpec& s : ParameterTable()) {
    const std::string rule = RuleText(s);
    out += fmt::format("| `{}/{}` | {} | {} | {} | {} |\n", s.group, s.key, s.unit, rule,
                       ParamValueText(s, defaults), s.meaning);
  }
  return out;
}

}  // namespace vahf::scene
