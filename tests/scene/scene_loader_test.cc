// Tests of the scene loader (ParseScene, LoadScene) and of LoadExperiment: a
// valid peg-in-hole scene parses, with masses equal to density times the
// closed-form volume of its profiles and parameter overrides in scene.params;
// every malformed variant of it (one mutation each) throws vahf::InputError
// naming the file, the exact JSON pointer, the value and the rule broken.
#include "vahf/scene/scene_loader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <ostream>
#include <set>
#include <string>
#include <utility>

#include "support/test_files.h"
#include "vahf/contact/contact_registry.h"
#include "vahf/core/error.h"
#include "vahf/human/factor_curves.h"
#include "vahf/kinds/kind.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/parameter_table.h"

namespace vahf::scene {

using kinds::LoadExperiment;
using kinds::ParseExperiment;
namespace {

using ::nlohmann::json;
using ::testing::HasSubstr;
using testing::Lower;
using testing::WriteFile;

constexpr char kFile[] = "test_scene.json";
constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The bore: a steel cylinder (radius kBoreRadius, height kBoreHeight, top face at
// z = 0) with a blind hole of radius kHoleRadius and depth kHoleDepth whose mouth
// has a 45-degree chamfer of kChamfer.
constexpr double kBoreRadius = 0.03;
constexpr double kBoreHeight = 0.05;
constexpr double kHoleRadius = 0.01;
constexpr double kHoleDepth = 0.04;
constexpr double kChamfer = 0.001;
constexpr double kBoreDensity = 7850.0;

// The peg: a rod of radius kPegRadius and length kPegLength whose bottom edge
// has a 45-degree chamfer of kPegChamfer.
constexpr double kPegRadius = 0.0099;
constexpr double kPegLength = 0.05;
constexpr double kPegChamfer = 0.0005;
constexpr double kPegDensity = 2700.0;

// Volume of a conical frustum of height h between radii a and b.
double FrustumVolume(double h, double a, double b) {
  return kPi * h / 3.0 * (a * a + a * b + b * b);
}

double BoreVolume() {
  const double cylinder = kPi * kBoreRadius * kBoreRadius * kBoreHeight;
  const double hole = kPi * kHoleRadius * kHoleRadius * (kHoleDepth - kChamfer) +
                      FrustumVolume(kChamfer, kHoleRadius, kHoleRadius + kChamfer);
  return cylinder - hole;
}

double PegVolume() {
  return kPi * kPegRadius * kPegRadius * (kPegLength - kPegChamfer) +
         FrustumVolume(kPegChamfer, kPegRadius - kPegChamfer, kPegRadius);
}

// A valid scene modelled on experiments/scenes/peg_in_hole.json. The peg's
// profile points are, by index: 0 (0, 0), 1 (r - c, 0), 2 (r, c), 3 (r, L),
// 4 (0, L), 5 (0, 0).
json ValidScene() {
  const json bore_profile = json::array({
      {0.0, -kBoreHeight},
      {kBoreRadius, -kBoreHeight},
      {kBoreRadius, 0.0},
      {kHoleRadius + kChamfer, 0.0},
      {kHoleRadius, -kChamfer},
      {kHoleRadius, -kHoleDepth},
      {0.0, -kHoleDepth},
      {0.0, -kBoreHeight},
  });
  const json peg_profile = json::array({
      {0.0, 0.0},
      {kPegRadius - kPegChamfer, 0.0},
      {kPegRadius, kPegChamfer},
      {kPegRadius, kPegLength},
      {0.0, kPegLength},
      {0.0, 0.0},
  });
  json bore = {
      {"name", "bore"},
      {"role", "base"},
      {"geometry", {{"type", "revolution"}, {"profile", bore_profile}}},
      {"density", kBoreDensity},
      {"friction", 0.15},
      {"pose", {{"position", {0.0, 0.0, 0.95}}}},
  };
  json peg = {
      {"name", "peg"},
      {"role", "assembling"},
      {"geometry", {{"type", "revolution"}, {"profile", peg_profile}}},
      {"density", kPegDensity},
      {"friction", 0.2},
      {"pose", {{"position", {0.002, 0.0, 0.97}}, {"rotation_xyz_deg", {3.0, 0.0, 0.0}}}},
      {"target", {{"position", {0.0, 0.0, 0.91}}}},
  };
  return {
      {"format", "vahf-scene/1"},
      {"name", "peg_in_hole_test"},
      {"description", "a chamfered peg into a chamfered blind bore"},
      {"operator",
       {{"height", 1.75},
        {"arm_length", 0.74},
        {"position", {0.0, -0.45}},
        {"facing_deg", 90},
        {"sex", "male"}}},
      {"parts", {bore, peg}},
      {"sequence", {"peg"}},
  };
}

// Parses `doc` and expects an InputError at `where` whose rule contains `rule`
// and, unless `value` is empty, whose value contains `value` (ignoring case).
void ExpectError(const json& doc, const std::string& where, const std::string& rule,
                 const std::string& value = "") {
  try {
    ParseScene(doc, kFile);
    ADD_FAILURE() << "no InputError; expected one at " << where << " (" << rule << ")";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), kFile) << e.what();
    EXPECT_EQ(e.where(), where) << e.what();
    EXPECT_THAT(e.rule(), HasSubstr(rule)) << e.what();
    if (!value.empty()) {
      EXPECT_THAT(Lower(e.value()), HasSubstr(Lower(value))) << e.what();
    }
  }
}

std::filesystem::path TestDir() { return testing::TestDir("vahf_scene_loader_test"); }

// ---------------------------------------------------------------------------
// The valid scene.

TEST(ParseSceneTest, ValidSceneParses) {
  const Scene scene = ParseScene(ValidScene(), kFile);
  EXPECT_EQ(scene.file, kFile);
  EXPECT_EQ(scene.name, "peg_in_hole_test");
  EXPECT_EQ(scene.description, "a chamfered peg into a chamfered blind bore");
  ASSERT_EQ(scene.parts.size(), 2u);

  const Part& bore = scene.parts[0];
  EXPECT_EQ(bore.name, "bore");
  EXPECT_EQ(bore.role, Role::kBase);
  EXPECT_TRUE(std::holds_alternative<geometry::RevolvedProfile>(bore.shape));
  EXPECT_DOUBLE_EQ(bore.friction, 0.15);
  EXPECT_EQ(bore.initial.position, Eigen::Vector3d(0.0, 0.0, 0.95));
  EXPECT_EQ(bore.target.position, bore.initial.position);  // fixed parts stay put

  const Part& peg = scene.parts[1];
  EXPECT_EQ(peg.name, "peg");
  EXPECT_EQ(peg.role, Role::kAssembling);
  EXPECT_DOUBLE_EQ(peg.friction, 0.2);
  EXPECT_EQ(peg.initial.position, Eigen::Vector3d(0.002, 0.0, 0.97));
  EXPECT_EQ(peg.initial.rotation_xyz_deg, Eigen::Vector3d(3.0, 0.0, 0.0));
  EXPECT_EQ(peg.target.position, Eigen::Vector3d(0.0, 0.0, 0.91));
  EXPECT_EQ(peg.target.rotation_xyz_deg, Eigen::Vector3d::Zero());

  EXPECT_EQ(scene.sequence, std::vector<int>{1});
  EXPECT_DOUBLE_EQ(scene.op.height, 1.75);
  EXPECT_DOUBLE_EQ(scene.op.arm_length, 0.74);
  EXPECT_EQ(scene.op.position, Eigen::Vector2d(0.0, -0.45));
  EXPECT_DOUBLE_EQ(scene.op.facing_deg, 90.0);
  EXPECT_EQ(scene.op.sex, "male");
  EXPECT_EQ(scene.gravity, Eigen::Vector3d(0.0, 0.0, -9.80665));  // the default
}

TEST(ParseSceneTest, MassIsDensityTimesClosedFormVolume) {
  const Scene scene = ParseScene(ValidScene(), kFile);
  const Part& bore = scene.parts[0];
  const Part& peg = scene.parts[1];
  // The profile integrals are exact for these polygons: only rounding differs.
  EXPECT_NEAR(bore.mass_properties.volume, BoreVolume(), 1e-12 * BoreVolume());
  EXPECT_NEAR(peg.mass_properties.volume, PegVolume(), 1e-12 * PegVolume());
  EXPECT_DOUBLE_EQ(bore.density, kBoreDensity);
  EXPECT_DOUBLE_EQ(peg.density, kPegDensity);
  EXPECT_NEAR(bore.mass, kBoreDensity * BoreVolume(), 1e-12 * bore.mass);
  EXPECT_NEAR(peg.mass, kPegDensity * PegVolume(), 1e-12 * peg.mass);
  // Sanity of the closed forms themselves: about 1.011 kg of steel, 41.5 g of
  // aluminium.
  EXPECT_NEAR(bore.mass, 1.01087, 1e-5);
  EXPECT_NEAR(peg.mass, 0.0415469, 1e-7);
}

TEST(ParseSceneTest, MassGivenSetsDensityFromVolume) {
  json doc = ValidScene();
  doc["parts"][1].erase("density");
  doc["parts"][1]["mass"] = 0.05;
  const Scene scene = ParseScene(doc, kFile);
  EXPECT_DOUBLE_EQ(scene.parts[1].mass, 0.05);
  EXPECT_NEAR(scene.parts[1].density, 0.05 / PegVolume(), 1e-12 * 0.05 / PegVolume());
}

TEST(ParseSceneTest, BoxPartVolumeIsProductOfEdges) {
  json doc = ValidScene();
  doc["parts"].push_back({{"name", "cover"},
                          {"role", "assembled"},
                          {"geometry", {{"type", "box"}, {"size", {0.1, 0.2, 0.01}}}},
                          {"mass", 0.54},
                          {"friction", 0.3},
                          {"pose", {{"position", {0.0, 0.0, 1.0}}}}});
  const Scene scene = ParseScene(doc, kFile);
  ASSERT_EQ(scene.parts.size(), 3u);
  const Part& cover = scene.parts[2];
  EXPECT_EQ(cover.role, Role::kAssembled);
  EXPECT_TRUE(std::holds_alternative<geometry::Box>(cover.shape));
  EXPECT_NEAR(cover.mass_properties.volume, 2e-4, 1e-18);
  EXPECT_NEAR(cover.density, 2700.0, 1e-9);
  EXPECT_EQ(scene.sequence, std::vector<int>{1});  // assembled parts stay out of it
}

TEST(ParseSceneTest, ParameterOverridesLandAndDefaultsStay) {
  json doc = ValidScene();
  doc["parameters"] = {
      {"fatigue", {{"k", 4.5}}},
      {"sight", {{"plateau_from_deg", 20}, {"value_at_0", 0.25}}},
      {"visibility", {{"mode", "constant"}, {"grid", 16}}},
      {"simulation", {{"integrator", "Verlet"}, {"time_limit", 12.5}}},
  };
  const Scene scene = ParseScene(doc, kFile);
  const Parameters& p = scene.params;
  EXPECT_DOUBLE_EQ(p.fatigue.k, 4.5);
  EXPECT_DOUBLE_EQ(p.sight.plateau_from_deg, 20.0);
  EXPECT_DOUBLE_EQ(p.sight.value_at_0, 0.25);
  EXPECT_EQ(p.visibility.mode, "constant");
  EXPECT_EQ(p.visibility.grid, 16);
  EXPECT_EQ(p.simulation.integrator, "Verlet");
  EXPECT_DOUBLE_EQ(p.simulation.time_limit, 12.5);

  // Every other parameter keeps its default.
  const std::set<std::pair<std::string, std::string>> overridden = {
      {"fatigue", "k"},
      {"sight", "plateau_from_deg"},
      {"sight", "value_at_0"},
      {"visibility", "mode"},
      {"visibility", "grid"},
      {"simulation", "integrator"},
      {"simulation", "time_limit"}};
  const Parameters defaults;
  int unchanged = 0;
  for (const ParamSpec& spec : ParameterTable()) {
    if (overridden.count({spec.group, spec.key})) {
      EXPECT_NE(ParamValueText(spec, p), ParamValueText(spec, defaults))
          << spec.group << "/" << spec.key;
      continue;
    }
    EXPECT_EQ(ParamValueText(spec, p), ParamValueText(spec, defaults))
        << spec.group << "/" << spec.key;
    ++unchanged;
  }
  EXPECT_EQ(unchanged + static_cast<int>(overridden.size()),
            static_cast<int>(ParameterTable().size()));
}

TEST(ParseSceneTest, WithoutParametersEveryParameterIsItsDefault) {
  const Scene scene = ParseScene(ValidScene(), kFile);
  const Parameters defaults;
  for (const ParamSpec& spec : ParameterTable())
    EXPECT_EQ(ParamValueText(spec, scene.params), ParamValueText(spec, defaults))
        << spec.group << "/" << spec.key;
  EXPECT_DOUBLE_EQ(scene.params.sight.plateau_to_deg,
                   human::DefaultSightCurve().plateau_to_deg);
  EXPECT_DOUBLE_EQ(scene.params.glance.plateau_to_deg,
                   human::DefaultGlanceCurve().plateau_to_deg);
}

TEST(ParseSceneTest, WhatReadsFileWhereValueRule) {
  json doc = ValidScene();
  doc["parts"][1]["friction"] = -0.5;
  try {
    ParseScene(doc, kFile);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "test_scene.json: /parts/1/friction = -0.5: must lie in [0, 5]");
  }
}

TEST(ParseSceneTest, ExampleSceneLoads) {
  const std::string path =
      std::string(VAHF_SOURCE_DIR) + "/experiments/scenes/peg_in_hole.json";
  const Scene scene = LoadScene(path);
  EXPECT_EQ(scene.file, path);
  EXPECT_EQ(scene.name, "peg_in_hole");
  ASSERT_EQ(scene.parts.size(), 2u);
  EXPECT_EQ(scene.parts[0].name, "bore");
  EXPECT_EQ(scene.parts[0].role, Role::kBase);
  EXPECT_EQ(scene.parts[1].name, "peg");
  EXPECT_EQ(scene.parts[1].role, Role::kAssembling);
  EXPECT_EQ(scene.sequence, std::vector<int>{1});
  EXPECT_GT(scene.parts[0].mass, 0.0);
  EXPECT_GT(scene.parts[1].mass, 0.0);
  EXPECT_THAT(DescribeScene(scene), HasSubstr("sequence: peg"));
}

TEST(ParseSceneTest, HydraulicCylinderHasItsStatedMassesAndFits) {
  // The generator's claims (tools/scenes/hydraulic_cylinder.py): about 9 kg in
  // all; ISO 286 H8/f7 at mid-tolerance gives 34 um radial clearance between
  // piston and barrel and 28 um between guide sleeve and rod.
  const Scene scene = LoadScene(std::string(VAHF_SOURCE_DIR) +
                                "/experiments/scenes/hydraulic_cylinder.json");
  ASSERT_EQ(scene.parts.size(), 4u);
  double total = 0;
  for (const Part& p : scene.parts) total += p.mass;
  EXPECT_NEAR(total, 9.2, 0.1);
  EXPECT_GT(scene.parts[1].mass, scene.parts[2].mass);  // rod > sleeve > seal ring
  EXPECT_GT(scene.parts[2].mass, scene.parts[3].mass);
  const auto radius_at = [](const Part& p, std::size_t k) {
    return std::get<geometry::RevolvedProfile>(p.shape).vertices.at(k).r;
  };
  // Profiles as generated (counter-clockwise): barrel vertex 4 the bore wall,
  // rod vertex 2 the piston, rod vertex 4 the rod, sleeve vertex 5 its bore.
  const double bore = radius_at(scene.parts[0], 4), piston = radius_at(scene.parts[1], 2);
  const double rod = radius_at(scene.parts[1], 4), sleeve = radius_at(scene.parts[2], 5);
  EXPECT_NEAR(bore - piston, 34e-6, 1e-9);
  EXPECT_NEAR(sleeve - rod, 28.5e-6, 1e-9);
  EXPECT_EQ(scene.sequence, (std::vector<int>{1, 2, 3}));
}

// ---------------------------------------------------------------------------
// Malformed scenes: each case is one mutation of ValidScene().

struct BadCase {
  const char* name;
  void (*mutate)(json& doc);
  const char* where;  // the exact JSON pointer of the error
  const char* rule;   // a substring of the rule
  const char* value;  // a substring of the value (ignoring case), "" to skip
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

json& Profile(json& doc, int part) {
  return doc["parts"][static_cast<std::size_t>(part)]["geometry"]["profile"];
}

const BadCase kBadCases[] = {
    // Structure and types.
    {"MissingFriction", [](json& d) { d["parts"][0].erase("friction"); },
     "/parts/0/friction", "required field 'friction' is missing", "(missing)"},
    {"MissingOperator", [](json& d) { d.erase("operator"); }, "/operator",
     "required field 'operator' is missing", "(missing)"},
    {"MissingTargetOnAssemblingPart", [](json& d) { d["parts"][1].erase("target"); },
     "/parts/1/target", "required field 'target' is missing", ""},
    {"DensityAsString", [](json& d) { d["parts"][1]["density"] = "7850"; },
     "/parts/1/density", "must be a number, not a string", "\"7850\""},
    {"HeightAsString", [](json& d) { d["operator"]["height"] = "1.75 m"; },
     "/operator/height", "must be a number, not a string", "1.75 m"},
    {"RootNotObject",
     [](json& d) {
       d = json::array({1, 2});
     },
     "/", "must be an object", ""},
    {"PartNotObject", [](json& d) { d["parts"][0] = "bore"; }, "/parts/0",
     "must be an object, not a string", "\"bore\""},
    {"PartsEmpty", [](json& d) { d["parts"] = json::array(); }, "/parts",
     "at least 1 element", ""},
    {"PositionTwoNumbers",
     [](json& d) {
       d["parts"][1]["pose"]["position"] = {0.0, 0.97};
     },
     "/parts/1/pose/position", "must be an array of 3 numbers", "[0.0,0.97]"},
    {"GravityElementString",
     [](json& d) {
       d["gravity"] = {0.0, 0.0, "down"};
     },
     "/gravity/2", "must be a number, not a string", "\"down\""},
    {"UnknownRole", [](json& d) { d["parts"][1]["role"] = "moving"; }, "/parts/1/role",
     "must be one of: base, assembling, assembled", "\"moving\""},
    {"UnknownGeometryType", [](json& d) { d["parts"][0]["geometry"]["type"] = "cone"; },
     "/parts/0/geometry/type", "must be one of: revolution, box", "\"cone\""},
    {"EmptyPartName", [](json& d) { d["parts"][0]["name"] = ""; }, "/parts/0/name",
     "non-empty name", ""},
    {"WrongFormat", [](json& d) { d["format"] = "vahf-scene/2"; }, "/format",
     "\"format\": \"vahf-scene/1\"", "vahf-scene/2"},
    {"FormatNotString", [](json& d) { d["format"] = 1; }, "/format",
     "must be a string, not a number", "1"},

    // Unknown keys.
    {"TypoDensty",
     [](json& d) {
       d["parts"][0]["densty"] = d["parts"][0]["density"];
       d["parts"][0].erase("density");
     },
     "/parts/0/densty", "unknown key 'densty' (did you mean 'density'?)", "7850"},
    {"TypoAtRootSequense",
     [](json& d) {
       d["sequense"] = d["sequence"];
       d.erase("sequence");
     },
     "/sequense", "did you mean 'sequence'?", ""},
    {"UnknownKeyEscapedInPointer", [](json& d) { d["parts/0"] = 1; }, "/parts~10",
     "unknown key 'parts/0'", ""},
    {"UnknownParameterGroup", [](json& d) { d["parameters"]["physics"]["k"] = 6; },
     "/parameters/physics", "unknown key 'physics' (known keys: sight, glance, reach",
     ""},
    {"TypoParameterGroup", [](json& d) { d["parameters"]["fatige"]["k"] = 6; },
     "/parameters/fatige", "did you mean 'fatigue'?", ""},
    {"UnknownParameterKey", [](json& d) { d["parameters"]["fatigue"]["kappa"] = 6; },
     "/parameters/fatigue/kappa", "unknown key 'kappa'", "6"},
    {"TypoParameterKey", [](json& d) { d["parameters"]["sight"]["value_at_90"] = 0.8; },
     "/parameters/sight/value_at_90", "did you mean 'value_at_0'?", "0.8"},

    // Non-finite numbers (only a program can put them in a json).
    {"FrictionInfinite", [](json& d) { d["parts"][1]["friction"] = kInf; },
     "/parts/1/friction", "must be a finite number", "inf"},
    {"DensityNaN", [](json& d) { d["parts"][0]["density"] = kNaN; }, "/parts/0/density",
     "must be a finite number", "nan"},
    {"HeightNaN", [](json& d) { d["operator"]["height"] = kNaN; }, "/operator/height",
     "must be a finite number", "nan"},
    {"GravityMinusInfinity",
     [](json& d) {
       d["gravity"] = {0.0, 0.0, -kInf};
     },
     "/gravity/2", "must be a finite number", "inf"},
    {"ProfileCoordinateNaN", [](json& d) { Profile(d, 1)[2][1] = kNaN; },
     "/parts/1/geometry/profile/2/1", "must be a finite number", "nan"},
    {"ParameterInfinite", [](json& d) { d["parameters"]["guidance"]["kappa"] = kInf; },
     "/parameters/guidance/kappa", "must be a finite number", "inf"},

    // Mass and density.
    {"NegativeMass",
     [](json& d) {
       d["parts"][1].erase("density");
       d["parts"][1]["mass"] = -0.1;
     },
     "/parts/1/mass", "must lie in [1e-4, 10000]", "-0.1"},
    {"ZeroMass",
     [](json& d) {
       d["parts"][1].erase("density");
       d["parts"][1]["mass"] = 0;
     },
     "/parts/1/mass", "must lie in [1e-4, 10000]", "0"},
    {"NegativeDensity", [](json& d) { d["parts"][0]["density"] = -7850; },
     "/parts/0/density", "must lie in [1, 1e7]", "-7850"},
    {"MassAndDensity", [](json& d) { d["parts"][1]["mass"] = 0.05; }, "/parts/1",
     "'density' or its 'mass', not both", ""},
    {"NeitherMassNorDensity", [](json& d) { d["parts"][1].erase("density"); },
     "/parts/1/mass", "a part needs its 'mass' (kg) or its 'density' (kg/m^3)",
     "(missing)"},
    {"NegativeFriction", [](json& d) { d["parts"][0]["friction"] = -0.15; },
     "/parts/0/friction", "must lie in [0, 5]", "-0.15"},

    // Geometry.
    {"OpenProfile", [](json& d) { Profile(d, 1).erase(5); }, "/parts/1/geometry/profile",
     "open, its last point", ""},
    {"BowTieProfile",
     [](json& d) {
       Profile(d, 1) = {{0.0, 0.0}, {0.01, 0.0}, {0.0, 0.05}, {0.01, 0.05}, {0.0, 0.0}};
     },
     "/parts/1/geometry/profile/3", "crosses or touches", "[0.01,0.05]"},
    {"NegativeRadius",
     [](json& d) {
       Profile(d, 1)[2] = {-0.01, 0.0005};
     },
     "/parts/1/geometry/profile/2", "is negative", "[-0.01,0.0005]"},
    {"TooFewPoints",
     [](json& d) {
       Profile(d, 1) = {{0.0, 0.0}, {0.01, 0.0}, {0.0, 0.0}};
     },
     "/parts/1/geometry/profile", "at least 3 distinct vertices", ""},
    {"RepeatedConsecutivePoint",
     [](json& d) {
       json& p = Profile(d, 1);
       p.insert(p.begin() + 3, p[2]);
     },
     "/parts/1/geometry/profile/3", "repeats the point before it", ""},
    {"ProfilePointThreeNumbers",
     [](json& d) {
       Profile(d, 0)[4] = {0.01, -0.001, 0.0};
     },
     "/parts/0/geometry/profile/4", "must be an array of 2 numbers", ""},
    {"ProfileNotArray", [](json& d) { Profile(d, 0) = "cylinder"; },
     "/parts/0/geometry/profile", "must be an array, not a string", "\"cylinder\""},
    {"DegenerateBox",
     [](json& d) {
       d["parts"][0]["geometry"] = {{"type", "box"}, {"size", {0.1, 0.0, 0.1}}};
     },
     "/parts/0/geometry/size", "degenerate", "[0.1,0.0,0.1]"},
    {"BoxWithProfileKey", [](json& d) { d["parts"][0]["geometry"]["type"] = "box"; },
     "/parts/0/geometry/profile", "unknown key 'profile'", ""},

    // The operator.
    {"HeightInCentimetres", [](json& d) { d["operator"]["height"] = 17.5; },
     "/operator/height", "must lie in [1, 2.5]", "17.5"},
    {"ArmLengthOutOfRange", [](json& d) { d["operator"]["arm_length"] = 74; },
     "/operator/arm_length", "must lie in [0.3, 1.2]", "74"},
    {"UnknownSex", [](json& d) { d["operator"]["sex"] = "m"; }, "/operator/sex",
     "must be one of: male, female, unspecified", "\"m\""},
    {"ReachBreakpointsNotIncreasing",
     [](json& d) {
       d["operator"]["arm_length"] = 0.95;
       d["operator"]["height"] = 1.6;
     },
     "/operator",
     "D1 = 0.85 * arm_length 0.95 m = 0.8075 m, D2 = 0.39 * height 1.6 m = 0.624 m",
     "height 1.6 m, arm_length 0.95 m"},
    {"ReachFractionMakesBreakpointsCross",
     [](json& d) { d["parameters"]["reach"]["d3_height_fraction"] = 0.3; }, "/operator",
     "need 0 < D1 < D2 < D3", "height 1.75"},

    // The sequence.
    {"EmptySequence", [](json& d) { d["sequence"] = json::array(); }, "/sequence",
     "the assembly sequence is empty", "[]"},
    {"SequenceNotArray", [](json& d) { d["sequence"] = "peg"; }, "/sequence",
     "must be an array, not a string", ""},
    {"SequenceUnknownPart", [](json& d) { d["sequence"] = {"pin"}; }, "/sequence/0",
     "names no part of this scene", "\"pin\""},
    {"SequenceNamesBase",
     [](json& d) {
       d["sequence"] = {"bore", "peg"};
     },
     "/sequence/0", "names a base part", "\"bore\""},
    {"SequenceNamesPartTwice",
     [](json& d) {
       d["sequence"] = {"peg", "peg"};
     },
     "/sequence/1", "names a part twice", "\"peg\""},
    {"AssemblingPartMissingFromSequence",
     [](json& d) {
       json peg2 = d["parts"][1];
       peg2["name"] = "peg2";
       d["parts"].push_back(peg2);
     },
     "/parts/2/role", "must appear in the sequence", "\"assembling\""},
    {"DuplicatePartName", [](json& d) { d["parts"][1]["name"] = "bore"; },
     "/parts/1/name", "part names must be unique", "\"bore\""},
    {"TargetOnBasePart",
     [](json& d) {
       d["parts"][0]["target"] = {{"position", {0.0, 0.0, 0.0}}};
     },
     "/parts/0/target", "'target' is only for assembling parts", ""},

    // Parameter values.
    {"SightValueAt0OutOfRange",
     [](json& d) { d["parameters"]["sight"]["value_at_0"] = 1.5; },
     "/parameters/sight/value_at_0", "must lie in [0, 1]", "1.5"},
    {"PlateauFromAfterTo",
     [](json& d) {
       d["parameters"]["sight"]["plateau_from_deg"] = 60;
       d["parameters"]["sight"]["plateau_to_deg"] = 40;
     },
     "/parameters/sight",
     "plateau must satisfy 0 < plateau_from_deg (60) < plateau_to_deg (40)", ""},
    {"GlancePlateauFromAfterDefaultTo",
     [](json& d) { d["parameters"]["glance"]["plateau_from_deg"] = 120; },
     "/parameters/glance", "plateau_from_deg (120) < plateau_to_deg (90)", ""},
    {"AngleOutOfRange", [](json& d) { d["parameters"]["sight"]["plateau_to_deg"] = 200; },
     "/parameters/sight/plateau_to_deg", "must lie in [0, 180]", "200"},
    {"NegativeKappa", [](json& d) { d["parameters"]["guidance"]["kappa"] = -1; },
     "/parameters/guidance/kappa", "must lie in (0, 1e6]", "-1"},
    {"GridNotInteger", [](json& d) { d["parameters"]["visibility"]["grid"] = 2.5; },
     "/parameters/visibility/grid", "must be an integer", "2.5"},
    {"GridZero", [](json& d) { d["parameters"]["visibility"]["grid"] = 0; },
     "/parameters/visibility/grid", "must lie in [1, 1024]", "0"},

    // Finite bounds the code can honour: each of these once
    // passed `check` and then aborted, hung or overflowed a trial.
    {"OperatorFarAway", [](json& d) { d["operator"]["position"][0] = 1e308; },
     "/operator/position/0", "must lie in [-100, 100]", "1e+308"},
    {"PoseFarAway", [](json& d) { d["parts"][1]["target"]["position"][2] = -1e308; },
     "/parts/1/target/position/2", "must lie in [-100, 100]", ""},
    {"RotationHuge", [](json& d) { d["parts"][1]["pose"]["rotation_xyz_deg"][0] = 1e20; },
     "/parts/1/pose/rotation_xyz_deg/0", "must lie in [-360, 360]", ""},
    {"GravityHuge",
     [](json& d) {
       d["gravity"] = {0.0, 0.0, -1e300};
     },
     "/gravity/2", "must lie in [-100, 100]", ""},
    {"DensityHuge", [](json& d) { d["parts"][1]["density"] = 1.7e308; },
     "/parts/1/density", "must lie in [1, 1e7]", ""},
    {"DensityGivesAMassBeyondTheRule", [](json& d) { d["parts"][1]["density"] = 1.0; },
     "/parts/1/density", "a part's mass lies in [1e-4, 10000] kg", ""},
    {"MassGivesADensityBeyondTheRule",
     [](json& d) {
       d["parts"][1].erase("density");
       d["parts"][1]["mass"] = 1e-4;  // the peg's 1.6e-5 m^3: 6.4 kg/m^3 is fine;
       Profile(d, 1)[3][1] = 5.0;     // a 5 m peg of 0.1 g is not
       Profile(d, 1)[4][1] = 5.0;
     },
     "/parts/1/mass", "a part's density lies in [1, 1e7] kg/m^3", ""},
    {"FrictionHuge", [](json& d) { d["parts"][1]["friction"] = 50; }, "/parts/1/friction",
     "must lie in [0, 5]", "50"},
    {"GraspOutsideThePart",
     [](json& d) {
       d["parts"][1]["grasp"] = {0.0, 0.0, 0.5};
     },
     "/parts/1/grasp", "within its bounding sphere", ""},
    {"ProfileBeyondTenMetres", [](json& d) { Profile(d, 1)[3][0] = 1e300; },
     "/parts/1/geometry/profile/3", "lies beyond 10 m", ""},
    {"ProfileTooSmall",
     [](json& d) {
       Profile(d, 1) =
           json::array({{0.0, 0.0}, {1e-6, 0.0}, {1e-6, 1e-6}, {0.0, 1e-6}, {0.0, 0.0}});
     },
     "/parts/1/geometry/profile", "encloses 1e-12 m^2; at least 1e-10 m^2", ""},
    {"ProfileTooManyVertices",
     [](json& d) {
       json p = json::array({{0.0, 0.0}});
       for (int k = 0; k <= 1000; ++k) p.push_back({0.005, 0.05 * k / 1000.0});
       p.push_back({0.0, 0.05});
       p.push_back({0.0, 0.0});
       Profile(d, 1) = p;
     },
     "/parts/1/geometry/profile", "a profile has at most 1000 vertices", ""},
    {"ContactShellTooFine",
     [](json& d) { d["parameters"]["contact"]["shell_spacing"] = 1e-5; },
     "/parameters/contact",
     "part 'peg': its contact shell at contact/shell_spacing 1e-05 m", ""},
    {"RimsTooFine",
     [](json& d) {
       d["parameters"]["contact"]["model"] = "resolving";
       d["parameters"]["contact"]["rim_spacing"] = 1e-5;
       d["parts"][1]["geometry"] = {{"type", "box"}, {"size", {10.0, 10.0, 10.0}}};
       d["parts"][1]["mass"] = 1e4;
       d["parts"][1].erase("density");
       d["parameters"]["contact"]["shell_spacing"] = 1.0;
     },
     "/parameters/contact", "its rims at contact/rim_spacing", ""},
    {"BoxEdgeTooLong",
     [](json& d) {
       d["parts"][1]["geometry"] = {{"type", "box"}, {"size", {20.0, 1.0, 1.0}}};
     },
     "/parts/1/geometry/size/0", "must lie in [1e-4, 10]", "20"},
    {"ContactBlendSubnormal",
     [](json& d) { d["parameters"]["guidance"]["contact_blend"] = 5e-324; },
     "/parameters/guidance/contact_blend", "must lie in [1e-3, 1000]", ""},
    {"DecisionIntervalTiny",
     [](json& d) { d["parameters"]["simulation"]["decision_interval"] = 5e-324; },
     "/parameters/simulation/decision_interval", "must lie in [1e-3, 10]", ""},
    {"UnknownIntegrator",
     [](json& d) { d["parameters"]["simulation"]["integrator"] = "Euler"; },
     "/parameters/simulation/integrator", "must be one of: RungeKuttaMerson",
     "\"Euler\""},
    {"ParametersNotObject", [](json& d) { d["parameters"] = json::array(); },
     "/parameters", "must be an object", ""},
};

class MalformedSceneTest : public ::testing::TestWithParam<BadCase> {};

TEST_P(MalformedSceneTest, ThrowsInputErrorAtItsPointer) {
  const BadCase& c = GetParam();
  json doc = ValidScene();
  c.mutate(doc);
  ExpectError(doc, c.where, c.rule, c.value);
}

// The rims' size bound holds for exactly the models whose entry says they
// build rims: a rim spacing too fine for the bore refuses those and no other.
TEST(ParseSceneTest, RimsAreBoundedForTheModelsThatBuildThem) {
  int with_rims = 0, without = 0;
  for (const contact::ContactModelEntry& e : contact::ContactModels()) {
    json doc = ValidScene();
    doc["parameters"]["contact"]["model"] = e.name;
    doc["parameters"]["contact"]["rim_spacing"] = 1e-5;
    doc["parts"][1]["geometry"] = {{"type", "box"}, {"size", {10.0, 10.0, 10.0}}};
    doc["parts"][1]["mass"] = 1e4;
    doc["parts"][1].erase("density");
    doc["parameters"]["contact"]["shell_spacing"] = 1.0;
    if (e.uses_rims) {
      ++with_rims;
      ExpectError(doc, "/parameters/contact", "its rims at contact/rim_spacing");
    } else {
      ++without;
      EXPECT_NO_THROW(ParseScene(doc, kFile)) << e.name;
    }
  }
  EXPECT_GE(with_rims, 1);
  EXPECT_GE(without, 1);
}

INSTANTIATE_TEST_SUITE_P(Scene, MalformedSceneTest, ::testing::ValuesIn(kBadCases),
                         [](const ::testing::TestParamInfo<BadCase>& param_info) {
                           return std::string(param_info.param.name);
                         });

TEST(BadCaseTableTest, CaseNamesAreUniqueAndEnough) {
  std::set<std::string> names;
  for (const BadCase& c : kBadCases) EXPECT_TRUE(names.insert(c.name).second) << c.name;
  EXPECT_GE(names.size(), 20u);
}

// ---------------------------------------------------------------------------
// LoadScene on files.

TEST(LoadSceneTest, MissingFile) {
  const std::string path = (TestDir() / "no_such_scene.json").string();
  try {
    LoadScene(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_THAT(e.rule(), HasSubstr("cannot open"));
  }
}

TEST(LoadSceneTest, InvalidJsonText) {
  const std::string path = WriteFile(TestDir() / "nan.json", "{\"format\": NaN}\n");
  try {
    LoadScene(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_THAT(e.rule(), HasSubstr("not valid JSON"));
    EXPECT_THAT(e.rule(), HasSubstr("line 1"));
  }
}

TEST(LoadSceneTest, ErrorsNameThePathOfTheFile) {
  json doc = ValidScene();
  doc["parts"][0]["friction"] = "high";
  const std::string path = WriteFile(TestDir() / "bad.json", doc.dump(2));
  try {
    LoadScene(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.where(), "/parts/0/friction");
    EXPECT_THAT(e.rule(), HasSubstr("must be a number"));
  }
}

TEST(LoadSceneTest, ValidFileRoundTrips) {
  const std::string path = WriteFile(TestDir() / "scene.json", ValidScene().dump(2));
  const Scene scene = LoadScene(path);
  EXPECT_EQ(scene.file, path);
  ASSERT_EQ(scene.parts.size(), 2u);
  EXPECT_NEAR(scene.parts[1].mass, kPegDensity * PegVolume(),
              1e-12 * scene.parts[1].mass);
}

// ---------------------------------------------------------------------------
// LoadExperiment.

json ValidExperiment() {
  return {{"format", "vahf-experiment/1"},
          {"name", "table1_check"},
          {"kind", "table1"},
          {"scene", "scenes/scene.json"},
          {"seed", 7},
          {"trials", 3}};
}

// Writes ValidScene() to DIR/scenes/scene.json and `experiment` to
// DIR/experiment.json; returns the experiment's path.
std::string WriteExperiment(const std::filesystem::path& dir, const json& experiment) {
  std::filesystem::create_directories(dir / "scenes");
  WriteFile(dir / "scenes" / "scene.json", ValidScene().dump(2));
  return WriteFile(dir / "experiment.json", experiment.dump(2));
}

void ExpectExperimentError(const json& experiment, const std::string& where,
                           const std::string& rule) {
  const std::string path = WriteExperiment(TestDir(), experiment);
  try {
    LoadExperiment(path);
    ADD_FAILURE() << "no InputError; expected one at " << where;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path) << e.what();
    EXPECT_EQ(e.where(), where) << e.what();
    EXPECT_THAT(e.rule(), HasSubstr(rule)) << e.what();
  }
}

TEST(LoadExperimentTest, ValidExperimentWithRelativeScenePath) {
  const std::filesystem::path dir = TestDir();
  const std::string path = WriteExperiment(dir, ValidExperiment());
  const ExperimentFile e = LoadExperiment(path);
  EXPECT_EQ(e.file, path);
  EXPECT_EQ(e.name, "table1_check");
  EXPECT_EQ(e.kind, "table1");
  EXPECT_EQ(e.seed, 7u);
  EXPECT_EQ(e.trials, 3);
  EXPECT_TRUE(std::filesystem::equivalent(e.scene_path, dir / "scenes" / "scene.json"))
      << e.scene_path;
  EXPECT_EQ(e.scene.file, e.scene_path);
  ASSERT_EQ(e.scene.parts.size(), 2u);
  EXPECT_EQ(e.scene.parts[1].name, "peg");
  EXPECT_EQ(FileFormatOf(path), "experiment");
  EXPECT_EQ(FileFormatOf(e.scene_path), "scene");
}

TEST(LoadExperimentTest, DefaultsForSeedAndTrials) {
  json experiment = ValidExperiment();
  experiment.erase("seed");
  experiment.erase("trials");
  const ExperimentFile e = LoadExperiment(WriteExperiment(TestDir(), experiment));
  EXPECT_EQ(e.seed, 1u);
  EXPECT_EQ(e.trials, 1);
}

TEST(LoadExperimentTest, UnknownKind) {
  json experiment = ValidExperiment();
  experiment["kind"] = "tabel1";
  ExpectExperimentError(experiment, "/kind", "must be one of: table1, assembly_time");
}

TEST(LoadExperimentTest, ScenePathDoesNotExist) {
  json experiment = ValidExperiment();
  experiment["scene"] = "scenes/missing.json";
  ExpectExperimentError(experiment, "/scene", "no scene file at");
}

TEST(LoadExperimentTest, NegativeSeed) {
  json experiment = ValidExperiment();
  experiment["seed"] = -1;
  ExpectExperimentError(experiment, "/seed", "must be a non-negative integer");
}

TEST(LoadExperimentTest, ZeroTrials) {
  json experiment = ValidExperiment();
  experiment["trials"] = 0;
  ExpectExperimentError(experiment, "/trials", "must lie in [1, 10000000]");
}

TEST(LoadExperimentTest, SceneFormatInAnExperimentFile) {
  json experiment = ValidExperiment();
  experiment["format"] = "vahf-scene/1";
  ExpectExperimentError(experiment, "/format", "\"format\": \"vahf-experiment/1\"");
}

TEST(LoadExperimentTest, ErrorInTheSceneNamesTheSceneFile) {
  const std::filesystem::path dir = TestDir();
  const std::string path = WriteExperiment(dir, ValidExperiment());
  json scene = ValidScene();
  scene["parts"][1]["mass"] = 0.05;  // and density: not both
  const std::string scene_path = WriteFile(dir / "scenes" / "scene.json", scene.dump(2));
  try {
    LoadExperiment(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::filesystem::equivalent(e.file(), scene_path)) << e.what();
    EXPECT_EQ(e.where(), "/parts/1");
    EXPECT_THAT(e.rule(), HasSubstr("not both"));
  }
}

}  // namespace
}  // namespace vahf::scene
