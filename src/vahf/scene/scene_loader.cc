#include "vahf/scene/scene_loader.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "vahf/contact/contact_registry.h"
#include "vahf/contact/point_shell.h"
#include "vahf/contact/rim.h"
#include "vahf/core/error.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/parameter_table.h"

namespace vahf::scene {
namespace {

// The bounds of a scene's numbers: finite bounds the code can honour
// (docs/scene-format.md, "Scene": the bounds). A workcell spans metres; 100 m holds any
// of them, and keeps the operator's shoulder offsets (centimetres) far above the rounding
// of a coordinate (2.2e-16 * 100 m = 2e-14 m).
constexpr double kMaxCoordinate = 100.0;  // m, every position
// Gravity up to 10 g: the Earth's 9.81 m/s^2 (ISO 80000-3), the Moon's, or none.
constexpr double kMaxGravity = 100.0;  // m/s^2, per component
// Part mass, kg: 0.1 g (a small seal) to 10 t. Density, kg/m^3: 1 (an
// aerogel) to 1e7, 400 times osmium's 22 590, so that a part may stand for a
// heavier assembly (a lumped mass, or the stability suite's 100 kg peg).
constexpr double kMinMass = 1e-4, kMaxMass = 1e4;
constexpr double kMinDensity = 1.0, kMaxDensity = 1e7;
// Coulomb friction coefficients of engineering pairs lie below about 1.5
// (rubber on dry steel); 5 leaves room for a deliberately extreme case.
constexpr double kMaxFriction = 5.0;

Pose ReadPose(const JsonNode& node) {
  node.ExpectObject({"position", "rotation_xyz_deg"});
  Pose pose;
  pose.position = node.Required("position").Vector3(-kMaxCoordinate, kMaxCoordinate);
  if (auto rot = node.Optional("rotation_xyz_deg"))
    pose.rotation_xyz_deg = rot->Vector3(-360.0, 360.0);
  return pose;
}

geometry::Shape ReadShape(const JsonNode& node) {
  const std::string type = node.Required("type").Choice({"revolution", "box"});
  if (type == "box") {
    node.ExpectObject({"type", "size"});
    const JsonNode size = node.Required("size");
    const Eigen::Vector3d s = size.Vector3();
    for (int k = 0; k < 3; ++k)
      if (!(s[k] > 0))
        size.Fail(
            "a box needs three positive edge lengths (m); a zero or negative edge "
            "makes it degenerate");
    for (int k = 0; k < 3; ++k)
      size.At(k).InRange(geometry::kMinBoxEdge, geometry::kMaxExtent);
    return geometry::Box{s};
  }
  node.ExpectObject({"type", "profile"});
  const JsonNode profile = node.Required("profile");
  const std::size_t n = profile.ArraySize();
  if (n > geometry::kMaxProfileVertices + 1)
    profile.Fail(
        fmt::format("{} points; a profile has at most {} vertices (and the "
                    "closing repeat)",
                    n, geometry::kMaxProfileVertices));
  std::vector<geometry::ProfilePoint> points;
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d rz = profile.At(k).Vector2();
    points.push_back({rz.x(), rz.y()});
  }
  try {
    return geometry::MakeRevolvedProfile(points);
  } catch (const geometry::ProfileError& e) {
    if (e.point() && *e.point() < n) profile.At(*e.point()).Fail(e.rule());
    profile.Fail(e.rule());
  }
}

Role ReadRole(const JsonNode& node) {
  const std::string s = node.Choice({"base", "assembling", "assembled"});
  if (s == "base") return Role::kBase;
  if (s == "assembling") return Role::kAssembling;
  return Role::kAssembled;
}

Part ReadPart(const JsonNode& node) {
  node.ExpectObject({"name", "role", "geometry", "density", "mass", "friction", "pose",
                     "target", "grasp", "description"});
  Part part;
  part.name = node.Required("name").String();
  if (part.name.empty()) node.Required("name").Fail("a part needs a non-empty name");
  part.role = ReadRole(node.Required("role"));
  part.shape = ReadShape(node.Required("geometry"));
  part.mass_properties = geometry::ComputeMassProperties(part.shape);
  const double volume = part.mass_properties.volume;
  const auto density = node.Optional("density");
  const auto mass = node.Optional("mass");
  if (density && mass) node.Fail("give a part's 'density' or its 'mass', not both");
  if (!density && !mass)
    throw InputError(node.file(), node.path() + "/mass", "(missing)",
                     "a part needs its 'mass' (kg) or its 'density' (kg/m^3)");
  if (density) {
    part.density = density->InRange(kMinDensity, kMaxDensity);
    part.mass = part.density * volume;
    if (!(part.mass >= kMinMass && part.mass <= kMaxMass))
      density->Fail(
          fmt::format("gives a mass of {:.6g} kg ({:.6g} m^3 of it); a part's mass "
                      "lies in [{}, {}] kg",
                      part.mass, volume, NumberText(kMinMass), NumberText(kMaxMass)));
  } else {
    part.mass = mass->InRange(kMinMass, kMaxMass);
    part.density = part.mass / volume;
    if (!(part.density >= kMinDensity && part.density <= kMaxDensity))
      mass->Fail(fmt::format(
          "gives a density of {:.6g} kg/m^3 ({:.6g} m^3 of it); a part's "
          "density lies in [{}, {}] kg/m^3",
          part.density, volume, NumberText(kMinDensity), NumberText(kMaxDensity)));
  }
  part.friction = node.Required("friction").InRange(0.0, kMaxFriction);
  part.grasp = part.mass_properties.centroid;
  if (auto grasp = node.Optional("grasp")) {
    part.grasp = grasp->Vector3(-kMaxCoordinate, kMaxCoordinate);
    // The hand holds the part: the grasp lies on it or in it, so within the
    // sphere about the part origin that holds the part.
    const double reach = part.mass_properties.bounding_radius;
    if (part.grasp.norm() > reach * (1 + 1e-9))
      grasp->Fail(
          fmt::format("lies {:.6g} m from the part origin; the hand holds the part, "
                      "so the grasp lies within its bounding sphere ({:.6g} m)",
                      part.grasp.norm(), reach));
  }
  part.initial = ReadPose(node.Required("pose"));
  if (part.role == Role::kAssembling) {
    part.target = ReadPose(node.Required("target"));
  } else {
    if (auto target = node.Optional("target"))
      target->Fail(std::string("a ") + RoleName(part.role) +
                   " part is fixed where its 'pose' puts it; 'target' is only for "
                   "assembling parts");
    part.target = part.initial;
  }
  return part;
}

human::Operator ReadOperator(const JsonNode& node) {
  node.ExpectObject({"height", "arm_length", "position", "facing_deg", "sex"});
  human::Operator op;
  // Stature of adults lies well inside 1.0-2.5 m (GB/T 10000-1988 1st-99th
  // percentiles: 1.45-1.81 m); anything outside is a unit mistake.
  op.height = node.Required("height").InRange(1.0, 2.5);
  op.arm_length = node.Required("arm_length").InRange(0.3, 1.2);
  op.position = node.Required("position").Vector2(-kMaxCoordinate, kMaxCoordinate);
  op.facing_deg = node.Required("facing_deg").InRange(-360.0, 360.0);
  if (auto sex = node.Optional("sex"))
    op.sex = sex->Choice({"male", "female", "unspecified"});
  return op;
}

void ReadParameters(const JsonNode& node, Parameters* p) {
  std::vector<std::string> groups;
  for (const ParamSpec& s : ParameterTable())
    if (std::find(groups.begin(), groups.end(), s.group) == groups.end())
      groups.push_back(s.group);
  node.ExpectObject(groups);
  for (const std::string& group : groups) {
    const auto g = node.Optional(group);
    if (!g) continue;
    std::vector<std::string> keys;
    for (const ParamSpec& s : ParameterTable())
      if (group == s.group) keys.push_back(s.key);
    g->ExpectObject(keys);
    for (const ParamSpec& s : ParameterTable()) {
      if (group != s.group) continue;
      const auto v = g->Optional(s.key);
      if (!v) continue;
      ReadParamValue(s, *v, p);
    }
  }
  // Rules that tie parameters together.
  for (const char* group : {"sight", "glance"}) {
    const human::PlateauCurve& c = std::string(group) == "sight" ? p->sight : p->glance;
    const std::string violation = c.Violation();
    if (!violation.empty()) {
      const auto g = node.Optional(group);
      (g ? *g : node).Fail(violation);
    }
  }
}

}  // namespace

std::vector<FixedPart> FixedPartsAt(const Scene& scene, std::size_t position) {
  std::vector<FixedPart> out;
  for (std::size_t k = 0; k < scene.parts.size(); ++k) {
    const Part& p = scene.parts[k];
    const auto seq =
        std::find(scene.sequence.begin(), scene.sequence.end(), static_cast<int>(k));
    const bool assembled_earlier =
        seq != scene.sequence.end() &&
        static_cast<std::size_t>(seq - scene.sequence.begin()) < position;
    if (p.role == Role::kAssembling && !assembled_earlier) continue;
    const Pose& pose = p.role == Role::kAssembling ? p.target : p.initial;
    out.push_back({&p, pose.Transform()});
  }
  return out;
}

std::optional<TightFit> TightestFit(const Part& part,
                                    const std::vector<FixedPart>& fixed) {
  std::optional<TightFit> best;
  for (const FixedPart& f : fixed)
    if (const auto fit = geometry::SmallestRadialFit(part.shape, part.target.Transform(),
                                                     f.part->shape, f.pose))
      if (!best || fit->clearance < best->fit.clearance) best = TightFit{*fit, f.part};
  return best;
}

const char* RoleName(Role role) {
  switch (role) {
    case Role::kBase:
      return "base";
    case Role::kAssembling:
      return "assembling";
    case Role::kAssembled:
      return "assembled";
  }
  return "?";
}

Scene ParseScene(const nlohmann::json& document, const std::string& file) {
  const JsonNode root(document, file);
  root.ExpectObject({"format", "name", "description", "gravity", "operator", "parts",
                     "sequence", "parameters"});
  const JsonNode format = root.Required("format");
  if (format.String() != kSceneFormat)
    format.Fail(std::string("a scene file declares \"format\": \"") + kSceneFormat +
                "\"");
  Scene scene;
  scene.file = file;
  scene.name = root.Required("name").String();
  if (auto d = root.Optional("description")) scene.description = d->String();
  if (auto g = root.Optional("gravity"))
    scene.gravity = g->Vector3(-kMaxGravity, kMaxGravity);
  scene.op = ReadOperator(root.Required("operator"));

  const JsonNode parts = root.Required("parts");
  const std::size_t n = parts.ArraySize(1);
  std::map<std::string, int> index_of;
  for (std::size_t k = 0; k < n; ++k) {
    Part part = ReadPart(parts.At(k));
    if (!index_of.emplace(part.name, static_cast<int>(k)).second)
      parts.At(k).Required("name").Fail("part names must be unique");
    scene.parts.push_back(std::move(part));
  }

  const JsonNode sequence = root.Required("sequence");
  const std::size_t m = sequence.ArraySize();
  if (m == 0) sequence.Fail("the assembly sequence is empty: name at least one part");
  for (std::size_t k = 0; k < m; ++k) {
    const JsonNode item = sequence.At(k);
    const std::string name = item.String();
    const auto it = index_of.find(name);
    if (it == index_of.end()) item.Fail("names no part of this scene");
    if (scene.parts[it->second].role != Role::kAssembling)
      item.Fail(std::string("names a ") + RoleName(scene.parts[it->second].role) +
                " part; the sequence lists assembling parts");
    if (std::find(scene.sequence.begin(), scene.sequence.end(), it->second) !=
        scene.sequence.end())
      item.Fail("names a part twice");
    scene.sequence.push_back(it->second);
  }
  for (std::size_t k = 0; k < n; ++k)
    if (scene.parts[k].role == Role::kAssembling &&
        std::find(scene.sequence.begin(), scene.sequence.end(), static_cast<int>(k)) ==
            scene.sequence.end())
      parts.At(k).Required("role").Fail("an assembling part must appear in the sequence");

  if (auto params = root.Optional("parameters")) ReadParameters(*params, &scene.params);
  const std::string reach =
      scene.params.reach.Violation(scene.op.arm_length, scene.op.height);
  if (!reach.empty()) {
    const JsonNode op = root.Required("operator");
    throw InputError(
        file, op.path(),
        fmt::format("height {} m, arm_length {} m", scene.op.height, scene.op.arm_length),
        reach);
  }
  RequireCountableSizes(scene);
  return scene;
}

Scene LoadScene(const std::string& path) { return ParseScene(ReadJsonFile(path), path); }

std::string DescribeScene(const Scene& s) {
  std::string out = fmt::format("scene '{}' ({})\n", s.name, s.file);
  if (!s.description.empty()) out += "  " + s.description + "\n";
  const human::ReachCurve::Breakpoints d =
      s.params.reach.BreakpointsFor(s.op.arm_length, s.op.height);
  out += fmt::format(
      "operator: {}, height {} m, arm length {} m, at ({}, {}) m facing {} deg; "
      "reach D1 {:.3f} m, D2 {:.3f} m, D3 {:.3f} m\n",
      s.op.sex, s.op.height, s.op.arm_length, s.op.position.x(), s.op.position.y(),
      s.op.facing_deg, d.d1, d.d2, d.d3);
  out += fmt::format("gravity: ({}, {}, {}) m/s^2\n", s.gravity.x(), s.gravity.y(),
                     s.gravity.z());
  out += fmt::format("parts ({}):\n", s.parts.size());
  for (const Part& p : s.parts) {
    const bool revolved = std::holds_alternative<geometry::RevolvedProfile>(p.shape);
    out += fmt::format(
        "  {:<14} {:<10} {:<10} mass {:.4g} kg, volume {:.4g} m^3, density {:.4g} "
        "kg/m^3, "
        "friction {}\n",
        p.name, RoleName(p.role), revolved ? "revolution" : "box", p.mass,
        p.mass_properties.volume, p.density, p.friction);
  }
  out += "sequence:";
  for (int i : s.sequence) out += " " + s.parts[i].name;
  out += "\nparameters (defaults unless the scene sets them):\n";
  for (const ParamSpec& spec : ParameterTable())
    out += fmt::format("  {}/{} = {} {}\n", spec.group, spec.key,
                       ParamValueText(spec, s.params), spec.unit);
  return out;
}

std::string SizeViolation(const Scene& scene) {
  const contact::ContactParams& c = scene.params.contact;
  const double rim_spacing = c.values.Get(contact::kRimSpacing);
  // "part 'rod': its contact shell at contact/shell_spacing 1e-5 m would ..."
  const auto over = [](const Part& part, const char* what, const char* key,
                       double spacing, double n, double max) {
    return n <= max ? std::string()
                    : fmt::format(
                          "part '{}': its {} at contact/{} {} m would hold up to "
                          "{:.3g} points, more than {:g}: raise the spacing",
                          part.name, what, key, spacing, n, max);
  };
  for (const Part& part : scene.parts) {
    std::string v;
    if (part.role == Role::kAssembling)
      v = over(part, "contact shell", "shell_spacing", c.shell_spacing,
               contact::PointShellSizeBound(part.shape, c.shell_spacing),
               contact::kMaxShellPoints);
    if (v.empty() && contact::FindContactModel(c.model).uses_rims)
      v = over(part, "rims", "rim_spacing", rim_spacing,
               contact::RimSizeBound(part.shape, rim_spacing), contact::kMaxRimPoints);
    if (!v.empty()) return v;
  }
  return "";
}

void RequireCountableSizes(const Scene& scene) {
  const std::string size = SizeViolation(scene);
  if (!size.empty())
    throw InputError(scene.file, "/parameters/contact",
                     fmt::format("shell_spacing {} m, rim_spacing {} m",
                                 scene.params.contact.shell_spacing,
                                 scene.params.contact.values.Get(contact::kRimSpacing)),
                     size);
}

std::string ParameterViolation(const Scene& scene) {
  for (const std::string& violation :
       {scene.params.sight.Violation(), scene.params.glance.Violation(),
        scene.params.reach.Violation(scene.op.arm_length, scene.op.height),
        SizeViolation(scene)})
    if (!violation.empty()) return violation;
  return "";
}

}  // namespace vahf::scene
