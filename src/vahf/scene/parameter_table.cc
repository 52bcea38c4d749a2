#include "vahf/scene/parameter_table.h"

#include <fmt/format.h>

#include "vahf/contact/contact_registry.h"

namespace vahf::scene {
namespace {

const char* RuleText(ParamRule rule) {
  switch (rule) {
    case ParamRule::kPositive: return "> 0";
    case ParamRule::kNonNegative: return ">= 0";
    case ParamRule::kUnit: return "in [0, 1]";
    case ParamRule::kOpenUnit: return "in (0, 1)";
    case ParamRule::kAngle: return "in [0, 180]";
    case ParamRule::kCount: return "integer >= 1";
    case ParamRule::kChoice: return "one of the names";
  }
  return "";
}

// "name: description; ..." of every registered contact model.
const std::string& ContactModelHelp() {
  static const std::string help = [] {
    std::string text;
    for (const contact::ContactModelEntry& e : contact::ContactModels())
      text += fmt::format("{}{}: {}", text.empty() ? "" : "; ", e.name, e.description);
    return text;
  }();
  return help;
}

#define VAHF_REAL(field) [](Parameters& p) -> double& { return p.field; }
#define VAHF_COUNT(field) [](Parameters& p) -> int& { return p.field; }
#define VAHF_TEXT(field) [](Parameters& p) -> std::string& { return p.field; }

std::vector<ParamSpec> MakeTable() {
  using R = ParamRule;
  std::vector<ParamSpec> t = {
      {"sight", "value_at_0", "1", R::kUnit, "f at Ang = 0 deg (Fig. 3)", VAHF_REAL(sight.value_at_0)},
      {"sight", "plateau_from_deg", "deg", R::kAngle, "f = 1 from this Ang (Sec. 3.2.1: 30)", VAHF_REAL(sight.plateau_from_deg)},
      {"sight", "plateau_to_deg", "deg", R::kAngle, "f = 1 up to this Ang (Sec. 3.2.1: 45)", VAHF_REAL(sight.plateau_to_deg)},
      {"sight", "value_at_180", "1", R::kUnit, "f at Ang = 180 deg", VAHF_REAL(sight.value_at_180)},
      {"glance", "value_at_0", "1", R::kUnit, "g at Anp = 0 deg (looking straight down, Fig. 5)", VAHF_REAL(glance.value_at_0)},
      {"glance", "plateau_from_deg", "deg", R::kAngle, "g = 1 from this Anp (Sec. 3.2.2: 30)", VAHF_REAL(glance.plateau_from_deg)},
      {"glance", "plateau_to_deg", "deg", R::kAngle, "g = 1 up to this Anp (Sec. 3.2.2: 90)", VAHF_REAL(glance.plateau_to_deg)},
      {"glance", "value_at_180", "1", R::kUnit, "g at Anp = 180 deg (looking straight up)", VAHF_REAL(glance.value_at_180)},
      {"reach", "d1_arm_fraction", "1", R::kPositive, "D1 = this * arm length (Sec. 3.2.2: 0.85)", VAHF_REAL(reach.d1_arm_fraction)},
      {"reach", "d2_height_fraction", "1", R::kPositive, "D2 = this * height (Sec. 3.2.2: 0.39)", VAHF_REAL(reach.d2_height_fraction)},
      {"reach", "d3_height_fraction", "1", R::kPositive, "D3 = this * height (Sec. 3.2.2: 0.68)", VAHF_REAL(reach.d3_height_fraction)},
      {"reach", "value_at_d2", "1", R::kUnit, "r at D2 (Fig. 4); r = 1 up to D1, 0 at D3", VAHF_REAL(reach.value_at_d2)},
      {"fatigue", "k", "1", R::kPositive, "K of Eq. 4 (Sec. 3.2.3: 6)", VAHF_REAL(fatigue.k)},
      {"fatigue", "a_max", "J", R::kPositive, "A at which Psi_c = 0 (Eq. 6: 1600 kcal)", VAHF_REAL(fatigue.a_max)},
      {"fatigue", "psi_floor", "1", R::kUnit, "Psi_c at or below which the operator is exhausted", VAHF_REAL(fatigue.psi_floor)},
      {"guidance", "kappa", "N/m", R::kPositive, "assembly force coefficient kappa (Eqs. 7, 8)", VAHF_REAL(guidance.kappa)},
      {"guidance", "mode", "-", R::kChoice, "operator: assembly force and torque act; none: they do not", nullptr, nullptr, VAHF_TEXT(guidance.mode), {"operator", "none"}},
      {"guidance", "damping_ratio", "1", R::kNonNegative, "damping of the force impedance, fraction of critical", VAHF_REAL(guidance.damping_ratio)},
      {"guidance", "weight_support", "1", R::kUnit, "fraction of the weight the operator carries in free motion", VAHF_REAL(guidance.weight_support)},
      {"guidance", "hand_mass", "kg", R::kNonNegative, "hand and forearm mass moving with the grasped part", VAHF_REAL(guidance.hand_mass)},
      {"guidance", "torque_frequency", "rad/s", R::kPositive, "natural frequency of the assembly torque impedance", VAHF_REAL(guidance.torque_frequency)},
      {"guidance", "torque_damping_ratio", "1", R::kNonNegative, "damping of the torque impedance, fraction of critical", VAHF_REAL(guidance.torque_damping_ratio)},
      {"guidance", "torque_sigma_deg", "deg", R::kAngle, "error of the held orientation per axis at eta = 1", VAHF_REAL(guidance.torque_sigma_deg)},
      {"guidance", "contact_blend", "1", R::kPositive, "contact normal force, in part weights, over which Eq. 7 passes into Eq. 8", VAHF_REAL(guidance.contact_blend)},
      {"guidance", "vision_sigma_depth", "m", R::kNonNegative, "E_i scale along the sight line at eta = 1 (Eq. 5)", VAHF_REAL(guidance.vision_sigma_depth)},
      {"guidance", "vision_sigma_lateral", "m", R::kNonNegative, "E_i scale across the sight line at eta = 1", VAHF_REAL(guidance.vision_sigma_lateral)},
      {"contact", "stiffness", "Pa/m", R::kPositive, "normal pressure per metre of penetration", VAHF_REAL(contact.stiffness)},
      {"contact", "onset_depth", "m", R::kPositive, "depth of the C1 quadratic onset of the normal law", VAHF_REAL(contact.onset_depth)},
      {"contact", "dissipation", "s/m", R::kNonNegative, "Hunt-Crossley dissipation", VAHF_REAL(contact.dissipation)},
      {"contact", "friction_transition_speed", "m/s", R::kPositive, "slip speed of the regularised Coulomb law", VAHF_REAL(contact.friction_transition_speed)},
      {"contact", "shell_spacing", "m", R::kPositive, "point spacing of the moving part's contact shell", VAHF_REAL(contact.shell_spacing)},
      {"contact", "line_stiffness", "Pa", R::kPositive, "line load per metre of penetration per metre of a static part's convex edge", VAHF_REAL(contact.line_stiffness)},
      {"contact", "rim_spacing", "m", R::kPositive, "sample spacing along the static parts' convex edges (rims)", VAHF_REAL(contact.rim_spacing)},
      {"contact", "penetration_fraction", "1", R::kPositive, "penetration bound as a fraction of the smallest radial clearance (a warning past it)", VAHF_REAL(contact.penetration_fraction)},
      {"contact", "model", "-", R::kChoice, ContactModelHelp().c_str(), nullptr, nullptr, VAHF_TEXT(contact.model), contact::ContactModelNames()},
      {"contact", "rule_contact_length", "m", R::kPositive, "edge length that carries the largest steady load (resolving model)", VAHF_REAL(contact.rule_contact_length)},
      {"contact", "rule_depth_fraction", "1", R::kUnit, "share of the bound the largest steady load may sink (resolving model)", VAHF_REAL(contact.rule_depth_fraction)},
      {"visibility", "mode", "-", R::kChoice, "raycast (Eq. 1), constant, or off (V = 1)", nullptr, nullptr, VAHF_TEXT(visibility.mode), {"raycast", "constant", "off"}},
      {"visibility", "value", "1", R::kUnit, "V when mode is constant", VAHF_REAL(visibility.value)},
      {"visibility", "grid", "rays", R::kCount, "N of the N x N ray grid", nullptr, VAHF_COUNT(visibility.grid)},
      {"visibility", "tessellation_tolerance", "m", R::kPositive, "chord error of part meshes", VAHF_REAL(visibility.tessellation_tolerance)},
      {"simulation", "decision_interval", "s", R::kPositive, "time between the operator's decisions", VAHF_REAL(simulation.decision_interval)},
      {"simulation", "time_limit", "s", R::kPositive, "a trial still running then ends as timeout", VAHF_REAL(simulation.time_limit)},
      {"simulation", "completion_distance", "m", R::kPositive, "d_th: complete when |T - T_t| is below it (Sec. 3.1)", VAHF_REAL(simulation.completion_distance)},
      {"simulation", "completion_angle_deg", "deg", R::kAngle, "and the angle to the target orientation is below it", VAHF_REAL(simulation.completion_angle_deg)},
      {"simulation", "jam_time", "s", R::kPositive, "in contact this long without progress: jammed", VAHF_REAL(simulation.jam_time)},
      {"simulation", "jam_progress", "m", R::kPositive, "approach to the target that counts as progress", VAHF_REAL(simulation.jam_progress)},
      {"simulation", "divergence_speed", "m/s", R::kPositive, "a part point faster than this: the integration diverged (numerical_failure)", VAHF_REAL(simulation.divergence_speed)},
      {"simulation", "integrator", "-", R::kChoice, "Simbody integrator, or CVODE (SUNDIALS BDF, without Simbody)", nullptr, nullptr, VAHF_TEXT(simulation.integrator), IntegratorNames()},
      {"simulation", "accuracy", "1", R::kOpenUnit, "integrator relative accuracy (Simbody's Integrator::setAccuracy asserts 0 < accuracy < 1)", VAHF_REAL(simulation.accuracy)},
      {"simulation", "fixed_step", "s", R::kPositive, "step of the FixedStep integrator", VAHF_REAL(simulation.fixed_step)},
      {"simulation", "velocity_time_scale", "s", R::kPositive, "CVODE: velocity tolerance = accuracy / this (m/s)", VAHF_REAL(simulation.velocity_time_scale)},
      {"simulation", "step_floor", "s", R::kPositive, "an accepted step shorter than this is a warning", VAHF_REAL(simulation.step_floor)},
  };
  return t;
}

#undef VAHF_REAL
#undef VAHF_COUNT
#undef VAHF_TEXT

}  // namespace

const std::vector<std::string>& IntegratorNames() {
  static const std::vector<std::string> names = {
      "RungeKuttaMerson", "RungeKutta3", "RungeKuttaFeldberg", "CPodes",
      "Verlet",           "SemiExplicitEuler2", "FixedStep",          "CVODE"};
  return names;
}

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
    case ParamRule::kPositive: s.real(*p) = v.Positive(); break;
    case ParamRule::kNonNegative: s.real(*p) = v.NonNegative(); break;
    case ParamRule::kUnit: s.real(*p) = v.InRange(0.0, 1.0); break;
    case ParamRule::kOpenUnit: {
      const double x = v.Number();
      if (!(x > 0 && x < 1)) v.Fail("must lie in (0, 1)");
      s.real(*p) = x;
      break;
    }
    case ParamRule::kAngle: s.real(*p) = v.InRange(0.0, 180.0); break;
    case ParamRule::kCount: s.count(*p) = static_cast<int>(v.Integer(1, 1 << 16)); break;
    case ParamRule::kChoice: s.text(*p) = v.Choice(s.choices); break;
  }
}

std::string ParamValueText(const ParamSpec& spec, const Parameters& p) {
  Parameters q = p;  // the accessors are the loader's, which writes through them
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
    std::string rule = RuleText(s.rule);
    if (s.rule == ParamRule::kChoice) {
      rule.clear();
      for (const auto& c : s.choices) rule += (rule.empty() ? "" : ", ") + c;
    }
    out += fmt::format("| `{}/{}` | {} | {} | {} | {} |\n", s.group, s.key, s.unit, rule,
                       ParamValueText(s, defaults), s.meaning);
  }
  return out;
}

}  // namespace vahf::scene
