// Tests of the experiment files' kind-specific keys (LoadExperiment): the
// shipped experiments/*.json load with their kinds, operators, conditions,
// instants, fatigue design, listed experiments and calibration design
// (parameters, targets, loss, relative_step); the operators of
// assembly_time.json are GB/T 10000-1988's (data/anthropometry/gb10000_1988.csv);
// and every malformed variant throws vahf::InputError naming the file that
// holds the fault, the exact JSON pointer, the value and the rule broken.
#include "vahf/scene/experiment_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/test_files.h"
#include "vahf/calibrate/calibration_input.h"
#include "vahf/compare/comparison_input.h"
#include "vahf/core/error.h"
#include "vahf/experiment/assembly_time_input.h"
#include "vahf/experiment/fatigue_input.h"
#include "vahf/experiment/groups_input.h"
#include "vahf/experiment/precision_input.h"
#include "vahf/experiment/stability_input.h"
#include "vahf/experiment/table1_input.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/paper_input.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::scene {

using calibrate::CalibrationDesign;
using calibrate::CalibrationStage;
using compare::ComparisonDesign;
using experiment::AssemblyTimeInput;
using experiment::ConditionEntry;
using experiment::DescribePrecision;
using experiment::FatigueInput;
using experiment::GroupsInput;
using experiment::PrecisionDesign;
using experiment::PrecisionScene;
using experiment::PrecisionSetting;
using experiment::SettingLabel;
using experiment::StabilityDesign;
using experiment::Table1Input;
using kinds::PaperInput;

using kinds::LoadExperiment;
using kinds::ParseExperiment;
namespace {

using ::nlohmann::json;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::Lower;
using testing::WriteFile;

std::string SourcePath(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

// The real scene, by absolute path.
std::string CylinderScene() {
  return SourcePath("experiments/scenes/hydraulic_cylinder.json");
}

std::filesystem::path TestDir() { return testing::TestDir("vahf_experiment_file_test"); }

std::string WriteJson(const std::filesystem::path& path, const json& doc) {
  return WriteFile(path, doc.dump(1));
}

// ---------------------------------------------------------------------------
// Valid experiments of each kind, on the real scene.

json Experiment(const std::string& kind) {
  return {{"format", "vahf-experiment/1"},
          {"name", kind + "_test"},
          {"kind", kind},
          {"scene", CylinderScene()},
          {"seed", 5},
          {"trials", 2}};
}

json Operator(const std::string& name, const std::string& sex, double height,
              double arm_length) {
  return {{"name", name},
          {"sex", sex},
          {"height", height},
          {"arm_length", arm_length},
          {"source", "test"}};
}

json AssemblyTime() {
  json e = Experiment("assembly_time");
  e["operators"] = {Operator("short", "female", 1.50, 0.62),
                    Operator("tall", "male", 1.80, 0.80)};
  return e;
}

json HumanFactorsGroups() {
  json e = Experiment("human_factors_groups");
  e["conditions"] = {{{"name", "general"}, {"scene", CylinderScene()}},
                     {{"name", "again"}, {"scene", CylinderScene()}}};
  e["instants_s"] = {2, 4.5, 8};
  e["paper_cycle_s"] = 8;
  return e;
}

json Fatigue() {
  json e = Experiment("fatigue");
  e["fatigue"] = {{"duration_min", 30}, {"segments", 3}, {"pilot_cycles", 5}};
  return e;
}

json Table1() {
  json e = Experiment("table1");
  e["paper_table"] = SourcePath("reference/paper/table1.json");
  return e;
}

// A paper experiment listing the files `listed` (written by the caller).
json Paper(const std::vector<std::string>& listed) {
  return {{"format", "vahf-experiment/1"},
          {"name", "paper_test"},
          {"kind", "paper"},
          {"seed", 9},
          {"experiments", listed}};
}

json Accuracy(const std::string& integrator, double accuracy) {
  return {{"simulation/integrator", integrator}, {"simulation/accuracy", accuracy}};
}

json Precision() {
  return {{"format", "vahf-experiment/1"},
          {"name", "precision_test"},
          {"kind", "precision"},
          {"seed", 3},
          {"trials", 4},
          {"scenes",
           {SourcePath("experiments/scenes/peg_in_hole.json"),
            {{"scene", CylinderScene()}, {"trials", 2}}}},
          {"reference", Accuracy("RungeKuttaMerson", 1e-8)},
          {"settings",
           {Accuracy("RungeKuttaMerson", 1e-3),
            Accuracy("CPodes", 2.5e-5),
            {{"visibility/grid", 16}},
            {{"contact/shell_spacing", 0.004}},
            {{"simulation/accuracy", 1e-5}}}},
          {"noise_trials", 10}};
}

// A calibration of kappa to the synthetic lab's times, on the steel block
// (docs/calibration.md), every optional key set away from its default.
json FitParam(const std::string& name, double start, double lower, double upper) {
  return {{"name", name}, {"start", start}, {"lower", lower}, {"upper", upper}};
}

json Calibrate() {
  json e = Experiment("calibrate");
  e["scene"] = SourcePath("experiments/scenes/steel_block_move.json");
  e["lab"] = SourcePath("data/synthetic_block/dataset.json");
  e["parameters"] = {FitParam("guidance/kappa", 400, 50, 2000),
                     FitParam("guidance/hand_mass", 1.0, 0.5, 2.0)};
  e["targets"] = {{{"quantity", "assembly_time"},
                   {"part", "block"},
                   {"by", "operator"},
                   {"variance", "pooled"}},
                  {{"quantity", "success_rate"}, {"part", "all"}}};
  e["loss"] = {{"kind", "cauchy"}, {"scale", 2}};
  e["relative_step"] = 0.1;
  e["max_iterations"] = 12;
  e["noise_replicates"] = 2;
  e["intervals"] = "profile";
  e["line_search"] = false;
  return e;
}

// Writes `doc` to DIR/experiment.json and expects LoadExperiment to throw an
// InputError naming that file at `where`, whose rule contains `rule` and,
// unless `value` is empty, whose value contains `value` (ignoring case).
void ExpectError(const json& doc, const std::string& where, const std::string& rule,
                 const std::string& value = "") {
  const std::string path = WriteJson(TestDir() / "experiment.json", doc);
  try {
    LoadExperiment(path);
    ADD_FAILURE() << "no InputError; expected one at " << where << " (" << rule << ")";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path) << e.what();
    EXPECT_EQ(e.where(), where) << e.what();
    EXPECT_THAT(e.rule(), HasSubstr(rule)) << e.what();
    if (!value.empty()) {
      EXPECT_THAT(Lower(e.value()), HasSubstr(Lower(value))) << e.what();
    }
  }
}

// ---------------------------------------------------------------------------
// The shipped experiments.

// A shipped experiment is named after its kind: KIND.json or KIND_VARIANT.json
// (precision_peg.json), so that a new kind's example needs no line here.
TEST(ShippedExperimentsTest, EveryFileLoadsWithItsKind) {
  std::set<std::string> found;
  for (const auto& entry :
       std::filesystem::directory_iterator(SourcePath("experiments"))) {
    if (entry.path().extension() != ".json") continue;
    const std::string name = entry.path().filename().string();
    const ExperimentFile e = LoadExperiment(entry.path().string());
    found.insert(e.kind);
    const std::string stem = entry.path().stem().string();
    EXPECT_TRUE(stem == e.kind || stem.rfind(e.kind + "_", 0) == 0)
        << name << " is not named after its kind " << e.kind;
    EXPECT_EQ(e.name, entry.path().stem().string()) << name;
    EXPECT_EQ(e.file, entry.path().string());
    EXPECT_FALSE(e.description.empty()) << name;
    if (name.find("_synthetic") != std::string::npos) {  // their own seeds and scene
      EXPECT_EQ(e.scene.name.rfind("steel_block_", 0), 0u) << name;  // a steel block's
      continue;
    }
    EXPECT_EQ(e.seed, 1u) << name;
    if (e.kind == "paper") {
      EXPECT_TRUE(e.scene_path.empty()) << name;
    } else if (e.kind == "precision") {  // its first scene
      EXPECT_EQ(e.scene_path, e.Input<PrecisionDesign>().scenes.at(0).path) << name;
    } else if (e.kind == "stability") {  // its first case's
      EXPECT_EQ(e.scene_path, e.Input<StabilityDesign>().cases.at(0).scene_path) << name;
      EXPECT_EQ(e.scene.name, "peg_in_hole_shell") << name;
    } else {
      EXPECT_EQ(e.scene.file, e.scene_path) << name;
    }
  }
  const std::vector<std::string> names = kinds::KindNames();  // each has an example
  EXPECT_EQ(found, std::set<std::string>(names.begin(), names.end()));
}

TEST(ShippedExperimentsTest, Table1ReadsThePaperTable) {
  const ExperimentFile e = LoadExperiment(SourcePath("experiments/table1.json"));
  EXPECT_TRUE(std::filesystem::equivalent(e.Input<Table1Input>().paper_table_path,
                                          SourcePath("reference/paper/table1.json")))
      << e.Input<Table1Input>().paper_table_path;
  // The manifest lists the table among the run's inputs.
  EXPECT_THAT(e.input->InputFiles(),
              ElementsAre(e.Input<Table1Input>().paper_table_path));
}

TEST(ShippedExperimentsTest, AssemblyTimeHasSixOperators) {
  const ExperimentFile e = LoadExperiment(SourcePath("experiments/assembly_time.json"));
  ASSERT_EQ(e.Input<AssemblyTimeInput>().operators.size(), 6u);
  std::vector<std::string> names, sexes;
  for (const OperatorEntry& o : e.Input<AssemblyTimeInput>().operators) {
    names.push_back(o.name);
    sexes.push_back(o.sex);
    EXPECT_THAT(o.source, HasSubstr("GB/T 10000-1988")) << o.name;
  }
  EXPECT_THAT(names, ElementsAre("male P5", "male P50", "male P95", "female P5",
                                 "female P50", "female P95"));
  EXPECT_THAT(sexes, ElementsAre("male", "male", "male", "female", "female", "female"));
  EXPECT_TRUE(e.input->InputFiles().empty());  // the scene only
}

TEST(ShippedExperimentsTest, HumanFactorsGroupsHasThreeConditions) {
  const ExperimentFile e =
      LoadExperiment(SourcePath("experiments/human_factors_groups.json"));
  ASSERT_EQ(e.Input<GroupsInput>().conditions.size(), 3u);
  EXPECT_EQ(e.Input<GroupsInput>().conditions[0].name, "general");
  EXPECT_EQ(e.Input<GroupsInput>().conditions[1].name, "best");
  EXPECT_EQ(e.Input<GroupsInput>().conditions[2].name, "worst");
  EXPECT_TRUE(std::filesystem::equivalent(e.Input<GroupsInput>().conditions[0].scene_path,
                                          CylinderScene()));
  EXPECT_TRUE(std::filesystem::equivalent(
      e.Input<GroupsInput>().conditions[1].scene_path,
      SourcePath("experiments/scenes/hydraulic_cylinder_best.json")));
  EXPECT_TRUE(std::filesystem::equivalent(
      e.Input<GroupsInput>().conditions[2].scene_path,
      SourcePath("experiments/scenes/hydraulic_cylinder_worst.json")));
  for (const ConditionEntry& c : e.Input<GroupsInput>().conditions) {
    EXPECT_EQ(c.scene.file, c.scene_path);
    EXPECT_EQ(c.scene.sequence.size(), 3u) << c.name;
  }
  EXPECT_THAT(e.Input<GroupsInput>().instants_s, ElementsAre(3, 6, 9, 12, 15));
  EXPECT_DOUBLE_EQ(e.Input<GroupsInput>().paper_cycle_s, 16.0);
}

TEST(ShippedExperimentsTest, FatigueIsOneHourInFourSegments) {
  const ExperimentFile e = LoadExperiment(SourcePath("experiments/fatigue.json"));
  EXPECT_DOUBLE_EQ(e.Input<FatigueInput>().fatigue.duration_min, 60.0);
  EXPECT_EQ(e.Input<FatigueInput>().fatigue.segments, 4);
  EXPECT_GT(e.Input<FatigueInput>().fatigue.pilot_cycles,
            0);  // a pilot measures the work rate
}

TEST(ShippedExperimentsTest, PaperListsTheFourExperiments) {
  const ExperimentFile e = LoadExperiment(SourcePath("experiments/paper.json"));
  EXPECT_TRUE(e.scene_path.empty());
  std::vector<std::string> kinds;
  for (const ExperimentFile& x : e.Input<PaperInput>().experiments) {
    kinds.push_back(x.kind);
    // The paper's experiments run its cylinder.
    EXPECT_TRUE(std::filesystem::equivalent(x.scene_path, CylinderScene())) << x.name;
    EXPECT_EQ(x.scene.name, "hydraulic_cylinder") << x.name;
  }
  EXPECT_THAT(kinds,
              ElementsAre("table1", "assembly_time", "human_factors_groups", "fatigue"));
  ASSERT_EQ(e.Input<PaperInput>().experiments.size(), 4u);
  // Each is loaded whole, from its own file (relative to paper.json's folder).
  EXPECT_TRUE(std::filesystem::equivalent(e.Input<PaperInput>().experiments[1].file,
                                          SourcePath("experiments/assembly_time.json")));
  EXPECT_EQ(
      e.Input<PaperInput>().experiments[1].Input<AssemblyTimeInput>().operators.size(),
      6u);
  EXPECT_EQ(e.Input<PaperInput>().experiments[2].Input<GroupsInput>().conditions.size(),
            3u);
  EXPECT_EQ(e.Input<PaperInput>().experiments[3].Input<FatigueInput>().fatigue.segments,
            4);
  EXPECT_FALSE(
      e.Input<PaperInput>().experiments[0].Input<Table1Input>().paper_table_path.empty());
}

// The operators of assembly_time.json are the 5th, 50th and 95th percentiles
// of GB/T 10000-1988: height = stature, arm length = upper arm + forearm +
// hand, in metres.
TEST(ShippedExperimentsTest, AssemblyTimeOperatorsMatchGb10000) {
  std::ifstream csv(SourcePath("data/anthropometry/gb10000_1988.csv"));
  ASSERT_TRUE(csv) << "cannot read data/anthropometry/gb10000_1988.csv";
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line, "sex,percentile,stature_mm,upper_arm_mm,forearm_mm,hand_mm");
  struct Row {
    std::string sex;
    double height, arm_length;
  };
  std::map<std::string, Row> rows;  // by operator name, "male P5"
  while (std::getline(csv, line)) {
    if (line.empty()) continue;
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) f.push_back(cell);
    ASSERT_EQ(f.size(), 6u) << line;
    const double stature = std::stod(f[2]);
    const double arm = std::stod(f[3]) + std::stod(f[4]) + std::stod(f[5]);
    rows[f[0] + " P" + f[1]] = {f[0], stature / 1000.0, arm / 1000.0};
  }
  ASSERT_EQ(rows.size(), 6u);

  const ExperimentFile e = LoadExperiment(SourcePath("experiments/assembly_time.json"));
  ASSERT_EQ(e.Input<AssemblyTimeInput>().operators.size(), rows.size());
  for (const OperatorEntry& o : e.Input<AssemblyTimeInput>().operators) {
    ASSERT_TRUE(rows.count(o.name)) << o.name << " is not in the CSV";
    const Row& r = rows.at(o.name);
    EXPECT_EQ(o.sex, r.sex) << o.name;
    EXPECT_NEAR(o.height, r.height, 1e-12) << o.name;
    EXPECT_NEAR(o.arm_length, r.arm_length, 1e-12) << o.name;
    // Stated in the source as "men 18-60, P5", "women 18-55, P50", ...
    EXPECT_THAT(o.source, HasSubstr(o.name.substr(o.name.find(' ') + 1))) << o.name;
    EXPECT_THAT(o.source, HasSubstr(o.sex == "male" ? "men" : "women")) << o.name;
  }
}

// ---------------------------------------------------------------------------
// Valid variants.

TEST(KindKeysTest, OperatorsLoad) {
  const ExperimentFile e =
      LoadExperiment(WriteJson(TestDir() / "e.json", AssemblyTime()));
  ASSERT_EQ(e.Input<AssemblyTimeInput>().operators.size(), 2u);
  EXPECT_EQ(e.Input<AssemblyTimeInput>().operators[0].name, "short");
  EXPECT_EQ(e.Input<AssemblyTimeInput>().operators[0].sex, "female");
  EXPECT_DOUBLE_EQ(e.Input<AssemblyTimeInput>().operators[0].height, 1.50);
  EXPECT_DOUBLE_EQ(e.Input<AssemblyTimeInput>().operators[0].arm_length, 0.62);
  EXPECT_EQ(e.Input<AssemblyTimeInput>().operators[0].source, "test");
  EXPECT_EQ(e.Input<AssemblyTimeInput>().operators[1].name, "tall");
  EXPECT_EQ(e.Input<AssemblyTimeInput>().operators[1].sex, "male");
}

TEST(KindKeysTest, OperatorsAreOptionalAndSourceToo) {
  json doc = Experiment("assembly_time");
  EXPECT_TRUE(LoadExperiment(WriteJson(TestDir() / "e.json", doc))
                  .Input<AssemblyTimeInput>()
                  .operators.empty());
  doc = AssemblyTime();
  doc["operators"][0].erase("source");
  const ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", doc));
  EXPECT_EQ(e.Input<AssemblyTimeInput>().operators[0].source, "");
}

TEST(KindKeysTest, OperatorsAtTheBoundsLoad) {
  json doc = AssemblyTime();
  doc["operators"] = {Operator("low", "female", 1.0, 0.3),
                      Operator("high", "male", 2.5, 1.1)};
  const ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", doc));
  EXPECT_EQ(e.Input<AssemblyTimeInput>().operators.size(), 2u);
}

TEST(KindKeysTest, ConditionsInstantsAndCycleLoad) {
  const ExperimentFile e =
      LoadExperiment(WriteJson(TestDir() / "e.json", HumanFactorsGroups()));
  ASSERT_EQ(e.Input<GroupsInput>().conditions.size(), 2u);
  EXPECT_EQ(e.Input<GroupsInput>().conditions[0].name, "general");
  EXPECT_EQ(e.Input<GroupsInput>().conditions[1].name, "again");
  EXPECT_EQ(e.Input<GroupsInput>().conditions[1].scene_path, CylinderScene());
  EXPECT_EQ(e.Input<GroupsInput>().conditions[1].scene.name, "hydraulic_cylinder");
  EXPECT_THAT(e.Input<GroupsInput>().instants_s,
              ElementsAre(2, 4.5, 8));  // the last one at the cycle's end
  EXPECT_DOUBLE_EQ(e.Input<GroupsInput>().paper_cycle_s, 8.0);
}

TEST(KindKeysTest, PaperCycleDefaultsTo16Seconds) {
  json doc = HumanFactorsGroups();
  doc.erase("paper_cycle_s");
  doc["instants_s"] = {16};
  const ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", doc));
  EXPECT_DOUBLE_EQ(e.Input<GroupsInput>().paper_cycle_s, 16.0);
}

TEST(KindKeysTest, ConditionScenesAreRelativeToTheExperimentFile) {
  const std::filesystem::path dir = TestDir();
  std::filesystem::create_directories(dir / "scenes");
  std::filesystem::copy_file(CylinderScene(), dir / "scenes" / "copy.json");
  json doc = HumanFactorsGroups();
  doc["conditions"][1]["scene"] = "scenes/copy.json";
  const ExperimentFile e = LoadExperiment(WriteJson(dir / "e.json", doc));
  EXPECT_TRUE(std::filesystem::equivalent(e.Input<GroupsInput>().conditions[1].scene_path,
                                          dir / "scenes" / "copy.json"));
}

TEST(KindKeysTest, FatigueDesignAndItsDefaults) {
  ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", Fatigue()));
  EXPECT_DOUBLE_EQ(e.Input<FatigueInput>().fatigue.duration_min, 30.0);
  EXPECT_EQ(e.Input<FatigueInput>().fatigue.segments, 3);
  EXPECT_EQ(e.Input<FatigueInput>().fatigue.pilot_cycles, 5);
  json doc = Fatigue();
  doc["fatigue"] = json::object();
  e = LoadExperiment(WriteJson(TestDir() / "e.json", doc));
  EXPECT_DOUBLE_EQ(e.Input<FatigueInput>().fatigue.duration_min, 60.0);
  EXPECT_EQ(e.Input<FatigueInput>().fatigue.segments, 4);
  EXPECT_EQ(e.Input<FatigueInput>().fatigue.pilot_cycles, 0);
  doc.erase("fatigue");
  e = LoadExperiment(WriteJson(TestDir() / "e.json", doc));
  EXPECT_DOUBLE_EQ(e.Input<FatigueInput>().fatigue.duration_min, 60.0);
}

TEST(KindKeysTest, PaperTableResolves) {
  const ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", Table1()));
  EXPECT_EQ(e.Input<Table1Input>().paper_table_path,
            SourcePath("reference/paper/table1.json"));
}

TEST(KindKeysTest, PaperLoadsItsListedExperiments) {
  const std::filesystem::path dir = TestDir();
  WriteJson(dir / "t.json", Table1());
  std::filesystem::create_directories(dir / "more");
  WriteJson(dir / "more" / "f.json", Fatigue());
  const ExperimentFile e =
      LoadExperiment(WriteJson(dir / "paper.json", Paper({"t.json", "more/f.json"})));
  EXPECT_EQ(e.kind, "paper");
  EXPECT_EQ(e.seed, 9u);
  EXPECT_TRUE(e.scene_path.empty());
  ASSERT_EQ(e.Input<PaperInput>().experiments.size(), 2u);
  EXPECT_EQ(e.Input<PaperInput>().experiments[0].kind, "table1");
  EXPECT_EQ(e.Input<PaperInput>().experiments[1].kind, "fatigue");
  EXPECT_TRUE(std::filesystem::equivalent(e.Input<PaperInput>().experiments[1].file,
                                          dir / "more" / "f.json"));
  EXPECT_EQ(e.Input<PaperInput>().experiments[1].Input<FatigueInput>().fatigue.segments,
            3);
}

// ---------------------------------------------------------------------------
// Operators (assembly_time).

TEST(OperatorErrorsTest, HeightAsString) {
  json doc = AssemblyTime();
  doc["operators"][1]["height"] = "NaN";
  ExpectError(doc, "/operators/1/height", "must be a number, not a string", "\"NaN\"");
}

TEST(OperatorErrorsTest, HeightAboveRange) {
  json doc = AssemblyTime();
  doc["operators"][0]["height"] = 3.0;
  ExpectError(doc, "/operators/0/height", "must lie in [1, 2.5]", "3");
}

TEST(OperatorErrorsTest, HeightBelowRange) {
  json doc = AssemblyTime();
  doc["operators"][0]["height"] = 0.99;
  ExpectError(doc, "/operators/0/height", "must lie in [1, 2.5]", "0.99");
}

TEST(OperatorErrorsTest, ArmLengthOutOfRange) {
  json doc = AssemblyTime();
  doc["operators"][1]["arm_length"] = 0.25;
  ExpectError(doc, "/operators/1/arm_length", "must lie in [0.3, 1.2]", "0.25");
  doc["operators"][1]["arm_length"] = 1.25;
  ExpectError(doc, "/operators/1/arm_length", "must lie in [0.3, 1.2]", "1.25");
}

TEST(OperatorErrorsTest, UnknownSex) {
  json doc = AssemblyTime();
  doc["operators"][0]["sex"] = "m";
  ExpectError(doc, "/operators/0/sex", "must be one of: male, female", "\"m\"");
}

TEST(OperatorErrorsTest, MissingFields) {
  for (const char* key : {"name", "sex", "height", "arm_length"}) {
    SCOPED_TRACE(key);
    json doc = AssemblyTime();
    doc["operators"][1].erase(key);
    ExpectError(doc, std::string("/operators/1/") + key,
                std::string("required field '") + key + "' is missing", "(missing)");
  }
}

TEST(OperatorErrorsTest, UnknownKey) {
  json doc = AssemblyTime();
  doc["operators"][0]["stature"] = 1.7;
  ExpectError(doc, "/operators/0/stature", "unknown key 'stature'", "1.7");
}

TEST(OperatorErrorsTest, DuplicateName) {
  json doc = AssemblyTime();
  doc["operators"].push_back(Operator("short", "male", 1.7, 0.7));
  ExpectError(doc, "/operators/2/name", "operator names must be unique", "\"short\"");
}

TEST(OperatorErrorsTest, EmptyList) {
  json doc = AssemblyTime();
  doc["operators"] = json::array();
  ExpectError(doc, "/operators", "at least 1 element");
}

TEST(OperatorErrorsTest, NotAnArrayOrNotObjects) {
  json doc = AssemblyTime();
  doc["operators"] = Operator("one", "male", 1.7, 0.7);
  ExpectError(doc, "/operators", "must be an array, not a object");
  doc = AssemblyTime();
  doc["operators"][1] = "tall";
  ExpectError(doc, "/operators/1", "must be an object, not a string", "\"tall\"");
}

TEST(OperatorErrorsTest, ReachCurveInvalidForTheOperator) {
  // Each dimension is in range, but D1 = 0.85 * 0.6 = 0.51 m lies beyond
  // D2 = 0.39 * 1.0 = 0.39 m.
  json doc = AssemblyTime();
  doc["operators"][1] = Operator("stubby", "male", 1.0, 0.6);
  ExpectError(doc, "/operators/1", "reach breakpoints must increase for this operator",
              "\"stubby\"");
}

TEST(OperatorErrorsTest, ReachCurveIsTheScenes) {
  // The operator's reach curve is the scene's: with D2 = 0.5 * height this
  // operator fits (D1 = 0.85 * 0.55 = 0.4675 m < D2 = 0.5 m).
  const std::filesystem::path dir = TestDir();
  std::ifstream in(CylinderScene());
  json scene = json::parse(in);
  scene["parameters"]["reach"]["d2_height_fraction"] = 0.5;
  WriteJson(dir / "wide_reach.json", scene);
  json doc = AssemblyTime();
  doc["scene"] = "wide_reach.json";
  doc["operators"][1] = Operator("stubby", "male", 1.0, 0.55);
  const ExperimentFile e = LoadExperiment(WriteJson(dir / "e.json", doc));
  EXPECT_EQ(e.Input<AssemblyTimeInput>().operators[1].name, "stubby");
  // With the shipped scene's reach (D2 = 0.39 m) the same operator fails.
  doc["scene"] = CylinderScene();
  ExpectError(doc, "/operators/1", "reach breakpoints must increase", "\"stubby\"");
}

// ---------------------------------------------------------------------------
// Conditions, instants and cycle (human_factors_groups).

TEST(ConditionErrorsTest, ConditionsRequired) {
  json doc = HumanFactorsGroups();
  doc.erase("conditions");
  ExpectError(doc, "/conditions", "required field 'conditions' is missing", "(missing)");
}

TEST(ConditionErrorsTest, ConditionsEmpty) {
  json doc = HumanFactorsGroups();
  doc["conditions"] = json::array();
  ExpectError(doc, "/conditions", "at least 1 element");
}

TEST(ConditionErrorsTest, ConditionSceneMissing) {
  json doc = HumanFactorsGroups();
  doc["conditions"][1]["scene"] = "no_such_scene.json";
  ExpectError(doc, "/conditions/1/scene", "no scene file at", "no_such_scene.json");
}

TEST(ConditionErrorsTest, ConditionWithoutScene) {
  json doc = HumanFactorsGroups();
  doc["conditions"][0].erase("scene");
  ExpectError(doc, "/conditions/0/scene", "required field 'scene' is missing");
}

TEST(ConditionErrorsTest, ConditionUnknownKey) {
  json doc = HumanFactorsGroups();
  doc["conditions"][0]["sceen"] = CylinderScene();
  ExpectError(doc, "/conditions/0/sceen", "did you mean 'scene'?");
}

TEST(ConditionErrorsTest, ErrorInAConditionSceneNamesThatScene) {
  const std::filesystem::path dir = TestDir();
  std::ifstream in(CylinderScene());
  json scene = json::parse(in);
  scene["operator"]["height"] = 3.0;
  const std::string bad_scene = WriteJson(dir / "bad_scene.json", scene);
  json doc = HumanFactorsGroups();
  doc["conditions"][1]["scene"] = "bad_scene.json";
  const std::string path = WriteJson(dir / "e.json", doc);
  try {
    LoadExperiment(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::filesystem::equivalent(e.file(), bad_scene)) << e.what();
    EXPECT_EQ(e.where(), "/operator/height") << e.what();
    EXPECT_EQ(e.value(), "3.0") << e.what();
  }
}

TEST(ConditionErrorsTest, InstantsRequired) {
  json doc = HumanFactorsGroups();
  doc.erase("instants_s");
  ExpectError(doc, "/instants_s", "required field 'instants_s' is missing", "(missing)");
}

TEST(ConditionErrorsTest, InstantsEmpty) {
  json doc = HumanFactorsGroups();
  doc["instants_s"] = json::array();
  ExpectError(doc, "/instants_s", "at least 1 element");
}

TEST(ConditionErrorsTest, InstantZeroOrNegative) {
  json doc = HumanFactorsGroups();
  doc["instants_s"][0] = 0;
  ExpectError(doc, "/instants_s/0", "must be > 0", "0");
  doc["instants_s"][0] = -3;
  ExpectError(doc, "/instants_s/0", "must be > 0", "-3");
}

TEST(ConditionErrorsTest, InstantAsString) {
  json doc = HumanFactorsGroups();
  doc["instants_s"][1] = "6 s";
  ExpectError(doc, "/instants_s/1", "must be a number, not a string", "\"6 s\"");
}

TEST(ConditionErrorsTest, InstantBeyondThePaperCycle) {
  json doc = HumanFactorsGroups();
  doc["instants_s"][2] = 8.5;  // paper_cycle_s is 8
  ExpectError(doc, "/instants_s/2", "an instant lies within the paper's cycle", "8.5");
  doc.erase("paper_cycle_s");  // the default, 16 s
  doc["instants_s"][2] = 16.5;
  ExpectError(doc, "/instants_s/2", "paper_cycle_s = 16", "16.5");
}

TEST(ConditionErrorsTest, PaperCycleNotPositive) {
  json doc = HumanFactorsGroups();
  doc["paper_cycle_s"] = 0;
  ExpectError(doc, "/paper_cycle_s", "must be > 0", "0");
  doc["paper_cycle_s"] = "16";
  ExpectError(doc, "/paper_cycle_s", "must be a number, not a string", "\"16\"");
}

// ---------------------------------------------------------------------------
// The fatigue design (fatigue).

TEST(FatigueErrorsTest, DurationNotPositive) {
  json doc = Fatigue();
  doc["fatigue"]["duration_min"] = 0;
  ExpectError(doc, "/fatigue/duration_min", "must be > 0", "0");
}

TEST(FatigueErrorsTest, SegmentsOutOfRange) {
  json doc = Fatigue();
  doc["fatigue"]["segments"] = 0;
  ExpectError(doc, "/fatigue/segments", "must lie in [1, 1000]", "0");
  doc["fatigue"]["segments"] = 2.5;
  ExpectError(doc, "/fatigue/segments", "must be an integer", "2.5");
}

TEST(FatigueErrorsTest, PilotCyclesNegative) {
  json doc = Fatigue();
  doc["fatigue"]["pilot_cycles"] = -1;
  ExpectError(doc, "/fatigue/pilot_cycles", "must lie in [0, 10000000]", "-1");
}

TEST(FatigueErrorsTest, UnknownKeyAndNotAnObject) {
  json doc = Fatigue();
  doc["fatigue"]["segment"] = 4;
  ExpectError(doc, "/fatigue/segment", "did you mean 'segments'?", "4");
  doc["fatigue"] = 60;
  ExpectError(doc, "/fatigue", "must be an object, not a number", "60");
}

// ---------------------------------------------------------------------------
// Paper tables (table1).

TEST(PaperTableErrorsTest, MissingPaperTable) {
  json doc = Table1();
  doc["paper_table"] = "no_such_table.json";
  ExpectError(doc, "/paper_table", "no paper table file at", "no_such_table.json");
}

// ---------------------------------------------------------------------------
// Paper experiments (paper).

TEST(PaperErrorsTest, PaperHasNoScene) {
  json doc = Paper({SourcePath("experiments/table1.json")});
  doc["scene"] = CylinderScene();
  ExpectError(doc, "/scene",
              "a paper experiment takes its scenes from the experiments it lists",
              "hydraulic_cylinder.json");
}

// A long value is shortened in the middle: the message keeps the start and
// the file name at the end of a path, whatever the directory's depth (CI
// clones into a deeper directory than a developer's checkout; the old
// shortening cut the file name off there).
TEST(PaperErrorsTest, LongValueKeepsBothEnds) {
  json doc = Paper({SourcePath("experiments/table1.json")});
  const std::string deep = "/start" + std::string(300, 'd') + "/hydraulic_cylinder.json";
  doc["scene"] = deep;
  const std::string path = WriteJson(TestDir() / "experiment.json", doc);
  try {
    LoadExperiment(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/scene") << e.what();
    EXPECT_LE(e.value().size(), 100u) << e.value();
    EXPECT_THAT(e.value(), ::testing::StartsWith("\"/start")) << e.value();
    EXPECT_THAT(e.value(), ::testing::EndsWith("/hydraulic_cylinder.json\""))
        << e.value();
    EXPECT_THAT(e.value(), HasSubstr("...")) << e.value();
  }
}

TEST(PaperErrorsTest, ExperimentsRequiredAndNotEmpty) {
  json doc = Paper({});
  ExpectError(doc, "/experiments", "at least 1 element");
  doc.erase("experiments");
  ExpectError(doc, "/experiments", "required field 'experiments' is missing",
              "(missing)");
}

TEST(PaperErrorsTest, ListedFileMissing) {
  json doc = Paper({SourcePath("experiments/table1.json"), "no_such_experiment.json"});
  ExpectError(doc, "/experiments/1", "no experiment file at", "no_such_experiment.json");
}

TEST(PaperErrorsTest, ListsAnotherPaperExperiment) {
  const std::filesystem::path dir = TestDir();
  WriteJson(dir / "inner.json", Paper({SourcePath("experiments/table1.json")}));
  const std::string path = WriteJson(
      dir / "outer.json", Paper({SourcePath("experiments/fatigue.json"), "inner.json"}));
  try {
    LoadExperiment(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path) << e.what();
    EXPECT_EQ(e.where(), "/experiments/1") << e.what();
    EXPECT_EQ(e.value(), "\"inner.json\"") << e.what();
    EXPECT_THAT(e.rule(), HasSubstr("a paper experiment cannot list another"))
        << e.what();
  }
}

// A paper experiment that lists itself is refused before it is parsed (it
// used to recurse until the stack overflowed).
TEST(PaperErrorsTest, ListsItself) {
  const std::filesystem::path dir = TestDir();
  const std::string path = WriteJson(dir / "self.json", Paper({"self.json"}));
  try {
    LoadExperiment(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/experiments/0") << e.what();
    EXPECT_THAT(e.rule(), HasSubstr("a paper experiment cannot list another"))
        << e.what();
  }
}

TEST(PaperErrorsTest, ErrorInAListedExperimentNamesThatFile) {
  const std::filesystem::path dir = TestDir();
  json listed = AssemblyTime();
  listed["operators"][0]["height"] = 3.0;
  const std::string listed_path = WriteJson(dir / "at.json", listed);
  const std::string path = WriteJson(dir / "paper.json", Paper({"at.json"}));
  try {
    LoadExperiment(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(std::filesystem::equivalent(e.file(), listed_path)) << e.what();
    EXPECT_EQ(e.where(), "/operators/0/height") << e.what();
    EXPECT_EQ(e.value(), "3.0") << e.what();
    EXPECT_THAT(e.rule(), HasSubstr("must lie in [1, 2.5]")) << e.what();
  }
}

// ---------------------------------------------------------------------------
// Precision experiments (precision).

TEST(PrecisionTest, ScenesReferenceAndSettingsLoad) {
  const ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", Precision()));
  const PrecisionDesign& d = e.Input<PrecisionDesign>();
  EXPECT_EQ(d.noise_trials, 10);
  EXPECT_EQ(d.reference.label, "reference: RungeKuttaMerson 1e-8");
  EXPECT_EQ(d.reference.pointer, "/reference");
  std::vector<std::string> labels, pointers;
  for (const PrecisionSetting& s : d.settings) {
    labels.push_back(s.label);
    pointers.push_back(s.pointer);
  }
  EXPECT_THAT(labels,
              ElementsAre("RungeKuttaMerson 1e-3", "CPodes 2.5e-5", "visibility/grid 16",
                          "contact/shell_spacing 4e-3", "simulation/accuracy 1e-5"));
  EXPECT_THAT(pointers, ElementsAre("/settings/0", "/settings/1", "/settings/2",
                                    "/settings/3", "/settings/4"));
  EXPECT_TRUE(d.settings[0].AccuracyOnly());
  EXPECT_FALSE(d.settings[2].AccuracyOnly());
  EXPECT_TRUE(d.settings[4].AccuracyOnly());  // the scene's integrator
  ASSERT_EQ(d.scenes.size(), 2u);
  EXPECT_EQ(d.scenes[0].scene.name, "peg_in_hole");
  EXPECT_EQ(d.scenes[0].trials, 0);  // the file's
  EXPECT_EQ(d.scenes[1].scene.name, "hydraulic_cylinder");
  EXPECT_EQ(d.scenes[1].trials, 2);
  EXPECT_EQ(e.scene_path, d.scenes[0].path);  // the manifest's scene
  EXPECT_EQ(e.trials, 4);
}

// Each setting is applied on top of each scene's own parameters: what it does
// not set keeps the scene's value (the cylinder sets shell_spacing 2 mm,
// hand_mass 1.5 kg, time_limit 10 s and CVODE at 1e-6).
TEST(PrecisionTest, ASettingKeepsTheScenesOtherParameters) {
  const ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", Precision()));
  const PrecisionScene& cylinder = e.Input<PrecisionDesign>().scenes[1];
  const Parameters& scene = cylinder.scene.params;
  EXPECT_DOUBLE_EQ(scene.contact.shell_spacing, 0.002);
  EXPECT_EQ(scene.simulation.integrator, "CVODE");
  EXPECT_DOUBLE_EQ(scene.simulation.accuracy, 1e-6);

  const Parameters& cpodes = cylinder.settings[1].params;
  EXPECT_EQ(cpodes.simulation.integrator, "CPodes");
  EXPECT_DOUBLE_EQ(cpodes.simulation.accuracy, 2.5e-5);
  EXPECT_DOUBLE_EQ(cpodes.contact.shell_spacing, 0.002);
  EXPECT_DOUBLE_EQ(cpodes.guidance.hand_mass, 1.5);
  EXPECT_DOUBLE_EQ(cpodes.simulation.time_limit, 10.0);

  const Parameters& grid = cylinder.settings[2].params;
  EXPECT_EQ(grid.visibility.grid, 16);
  EXPECT_DOUBLE_EQ(grid.simulation.accuracy, 1e-6);  // the scene's, not the reference's

  const Parameters& shell = cylinder.settings[3].params;
  EXPECT_DOUBLE_EQ(shell.contact.shell_spacing, 0.004);
  const Parameters& accuracy = cylinder.settings[4].params;
  EXPECT_EQ(accuracy.simulation.integrator, "CVODE");  // the scene's
  EXPECT_DOUBLE_EQ(accuracy.simulation.accuracy, 1e-5);

  EXPECT_DOUBLE_EQ(cylinder.reference.params.simulation.accuracy, 1e-8);
  EXPECT_DOUBLE_EQ(cylinder.reference.params.contact.shell_spacing, 0.002);
  // The peg sets no shell spacing: the default.
  EXPECT_DOUBLE_EQ(
      e.Input<PrecisionDesign>().scenes[0].settings[1].params.contact.shell_spacing,
      Parameters().contact.shell_spacing);
}

TEST(PrecisionTest, NoiseTrialsDefault) {
  json doc = Precision();
  doc.erase("noise_trials");
  const ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", doc));
  EXPECT_EQ(e.Input<PrecisionDesign>().noise_trials,
            PrecisionDesign::kDefaultNoiseTrials);
  // The most cycles per condition of any paper experiment.
  // Held by name: a range-for over a member of a temporary would read it freed.
  const ExperimentFile paper = LoadExperiment(SourcePath("experiments/paper.json"));
  int most = 0;
  for (const ExperimentFile& x : paper.Input<PaperInput>().experiments)
    most = std::max(most, x.trials);
  EXPECT_EQ(PrecisionDesign::kDefaultNoiseTrials, most);
}

TEST(PrecisionTest, LabelsAreReadable) {
  using Overrides = std::vector<std::pair<std::string, json>>;
  EXPECT_EQ(SettingLabel(Overrides{{"simulation/accuracy", 1e-4},
                                   {"simulation/integrator", "CPodes"}}),
            "CPodes 1e-4");
  EXPECT_EQ(SettingLabel(Overrides{{"visibility/grid", 16}}), "visibility/grid 16");
  EXPECT_EQ(SettingLabel(Overrides{{"contact/stiffness", 1e10}}),
            "contact/stiffness 1e10");
  EXPECT_EQ(SettingLabel(Overrides{{"guidance/kappa", 400.0}}), "guidance/kappa 400");
  EXPECT_EQ(SettingLabel(Overrides{{"simulation/accuracy", 0.05}}),
            "simulation/accuracy 0.05");
  EXPECT_EQ(SettingLabel(Overrides{{"simulation/accuracy", 1.0 / 3e6}}),
            "simulation/accuracy 3.3333333333333335e-7");
  EXPECT_EQ(SettingLabel(Overrides{{"visibility/mode", "off"}, {"visibility/grid", 8}}),
            "visibility/mode off, visibility/grid 8");
  EXPECT_EQ(SettingLabel(Overrides{}), "scene parameters");
  // Integrator and accuracy first, whatever else the setting changes.
  EXPECT_EQ(SettingLabel(Overrides{{"simulation/accuracy", 1e-4},
                                   {"simulation/integrator", "CVODE"},
                                   {"simulation/velocity_time_scale", 0.1}}),
            "CVODE 1e-4, simulation/velocity_time_scale 0.1");
}

TEST(PrecisionTest, CheckListsScenesReferenceAndSettings) {
  const ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", Precision()));
  const std::string text = DescribePrecision(e);
  EXPECT_THAT(text, HasSubstr("Monte Carlo noise of an experiment with 10 cycles"));
  EXPECT_THAT(text, HasSubstr("peg_in_hole ("));
  EXPECT_THAT(text, HasSubstr("): 1 part(s), 4 cycles per setting"));
  EXPECT_THAT(text, HasSubstr("): 3 part(s), 2 cycles per setting"));
  EXPECT_THAT(text, HasSubstr("reference: RungeKuttaMerson 1e-8 (/reference): "
                              "simulation/accuracy = 1e-08, simulation/integrator = "
                              "\"RungeKuttaMerson\""));
  EXPECT_THAT(text, HasSubstr("settings (5):"));
  EXPECT_THAT(text, HasSubstr("visibility/grid 16"));
  EXPECT_THAT(text, HasSubstr("(/settings/3): contact/shell_spacing = 0.004"));
}

TEST(PrecisionErrorsTest, UnknownParameterName) {
  json doc = Precision();
  doc["settings"][1]["simulation/acuracy"] = 1e-4;
  ExpectError(doc, "/settings/1/simulation~1acuracy",
              "unknown key 'simulation/acuracy' (did you mean 'simulation/accuracy'?)",
              "0.0001");
  doc = Precision();
  doc["reference"]["accuracy"] = 1e-8;
  ExpectError(doc, "/reference/accuracy", "unknown key 'accuracy'");
}

TEST(PrecisionErrorsTest, ValueBreaksTheParametersRule) {
  json doc = Precision();
  doc["settings"][3] = Accuracy("RungeKuttaMerson", -1e-3);
  ExpectError(doc, "/settings/3/simulation~1accuracy", "must lie in [1e-12, 0.5]",
              "-0.001");
  doc["settings"][3] = Accuracy("RungeKutta4", 1e-3);
  ExpectError(doc, "/settings/3/simulation~1integrator", "must be one of",
              "\"RungeKutta4\"");
  doc["settings"][3] = {{"visibility/grid", 2.5}};
  ExpectError(doc, "/settings/3/visibility~1grid", "must be an integer", "2.5");
  doc["settings"][3] = {{"guidance/weight_support", 1.5}};
  ExpectError(doc, "/settings/3/guidance~1weight_support", "must lie in [0, 1]", "1.5");
  doc = Precision();
  doc["reference"]["simulation/accuracy"] = "1e-8";
  ExpectError(doc, "/reference/simulation~1accuracy", "must be a number, not a string");
}

TEST(PrecisionErrorsTest, WholeMessageNamesFilePointerValueAndRule) {
  json doc = Precision();
  doc["settings"][3] = Accuracy("CPodes", 0);
  const std::string path = WriteJson(TestDir() / "experiment.json", doc);
  try {
    LoadExperiment(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        path + ": /settings/3/simulation~1accuracy = 0.0: must lie in [1e-12, 0.5]");
  }
}

// The rules that tie parameters together are checked on each scene with the
// setting applied, and name the setting.
TEST(PrecisionErrorsTest, RulesThatTieParametersTogether) {
  json doc = Precision();
  doc["settings"][2] = {{"sight/plateau_from_deg", 50}};  // beyond plateau_to_deg 45
  ExpectError(doc, "/settings/2", "applied to scene 'peg_in_hole'");
  ExpectError(doc, "/settings/2", "the plateau must satisfy 0 < plateau_from_deg (50)");
  doc = Precision();
  doc["reference"]["reach/d1_arm_fraction"] = 1.0;  // D1 = 0.74 m > D2 = 0.68 m
  ExpectError(doc, "/reference", "reach breakpoints must increase for this operator");
}

TEST(PrecisionErrorsTest, RequiredKeysAndTheirShapes) {
  for (const char* key : {"scenes", "reference", "settings"}) {
    SCOPED_TRACE(key);
    json doc = Precision();
    doc.erase(key);
    ExpectError(doc, std::string("/") + key,
                std::string("required field '") + key + "' is missing", "(missing)");
  }
  json doc = Precision();
  doc["settings"] = json::array();
  ExpectError(doc, "/settings", "at least 1 element");
  doc["settings"] = {Accuracy("CPodes", 1e-4), "fast"};
  ExpectError(doc, "/settings/1", "must be an object, not a string", "\"fast\"");
  doc = Precision();
  doc["reference"] = 1e-8;
  ExpectError(doc, "/reference", "must be an object, not a number");
  doc = Precision();
  doc["scenes"] = json::array();
  ExpectError(doc, "/scenes", "at least 1 element");
}

TEST(PrecisionErrorsTest, RepeatedSettings) {
  json doc = Precision();
  doc["settings"].push_back(Accuracy("CPodes", 2.5e-5));
  ExpectError(doc, "/settings/5", "repeats the setting at /settings/1");
  doc = Precision();
  doc["settings"][2] = Accuracy("RungeKuttaMerson", 1e-8);
  ExpectError(doc, "/settings/2", "repeats the reference");
}

TEST(PrecisionErrorsTest, NoiseTrialsOutOfRange) {
  json doc = Precision();
  doc["noise_trials"] = 0;
  ExpectError(doc, "/noise_trials", "must lie in [1, 10000000]", "0");
  doc["noise_trials"] = 2.5;
  ExpectError(doc, "/noise_trials", "must be an integer", "2.5");
}

TEST(PrecisionErrorsTest, Scenes) {
  json doc = Precision();
  doc["scenes"][1] = "no_such_scene.json";
  ExpectError(doc, "/scenes/1", "no scene file at", "no_such_scene.json");
  doc = Precision();
  doc["scenes"][1]["trials"] = 0;
  ExpectError(doc, "/scenes/1/trials", "must lie in [1, 10000000]", "0");
  doc = Precision();
  doc["scenes"][1]["trails"] = 3;
  ExpectError(doc, "/scenes/1/trails", "did you mean 'trials'?");
  doc = Precision();
  doc["scenes"][1] = {{"trials", 3}};
  ExpectError(doc, "/scenes/1/scene", "required field 'scene' is missing");
  doc = Precision();
  doc["scenes"].push_back(SourcePath("experiments/scenes/peg_in_hole.json"));
  ExpectError(doc, "/scenes/2", "scene names must be unique in a precision experiment");
  doc = Precision();
  doc["scene"] = CylinderScene();
  ExpectError(doc, "/scene", "a precision experiment names its scenes in \"scenes\"");
}

// ---------------------------------------------------------------------------
// Calibrations (calibrate).

TEST(CalibrateTest, ParametersTargetsLossAndStepsLoad) {
  const ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", Calibrate()));
  EXPECT_EQ(e.kind, "calibrate");
  EXPECT_EQ(e.scene.name, "steel_block_move");
  const CalibrationDesign& d = e.Input<CalibrationDesign>();
  EXPECT_TRUE(std::filesystem::equivalent(
      d.lab_path, SourcePath("data/synthetic_block/dataset.json")))
      << d.lab_path;
  ASSERT_EQ(d.stages.size(), 1u);
  const CalibrationStage& st = d.stages[0];
  EXPECT_EQ(st.name, "");
  EXPECT_EQ(st.solver, "levenberg_marquardt");
  ASSERT_EQ(st.parameters.size(), 2u);
  EXPECT_EQ(st.parameters[0].name, "guidance/kappa");
  EXPECT_DOUBLE_EQ(st.parameters[0].start, 400);
  EXPECT_DOUBLE_EQ(st.parameters[0].lower, 50);
  EXPECT_DOUBLE_EQ(st.parameters[0].upper, 2000);
  EXPECT_EQ(st.parameters[0].pointer, "/parameters/0");
  EXPECT_EQ(st.parameters[1].name, "guidance/hand_mass");
  EXPECT_DOUBLE_EQ(st.parameters[1].start, 1.0);
  EXPECT_DOUBLE_EQ(st.parameters[1].lower, 0.5);
  EXPECT_DOUBLE_EQ(st.parameters[1].upper, 2.0);
  EXPECT_EQ(st.parameters[1].pointer, "/parameters/1");
  ASSERT_EQ(st.targets.size(), 2u);
  EXPECT_EQ(st.targets[0].quantity, "assembly_time");
  EXPECT_EQ(st.targets[0].part, "block");
  EXPECT_TRUE(st.targets[0].by_operator);
  EXPECT_TRUE(st.targets[0].pooled_variance);
  EXPECT_EQ(st.targets[0].pointer, "/targets/0");
  EXPECT_EQ(st.targets[1].quantity, "success_rate");
  EXPECT_EQ(st.targets[1].part, "all");
  EXPECT_FALSE(st.targets[1].by_operator);      // "by" defaults to "all"
  EXPECT_FALSE(st.targets[1].pooled_variance);  // "variance" defaults to "own"
  EXPECT_EQ(st.targets[1].pointer, "/targets/1");
  EXPECT_EQ(d.loss, "cauchy");
  EXPECT_DOUBLE_EQ(d.loss_scale, 2.0);
  EXPECT_DOUBLE_EQ(d.relative_step, 0.1);
  EXPECT_EQ(d.max_iterations, 12);
  EXPECT_EQ(d.noise_replicates, 2);
  EXPECT_EQ(d.intervals, "profile");
  EXPECT_FALSE(d.line_search);
  EXPECT_EQ(e.seed, 5u);
  EXPECT_EQ(e.trials, 2);
}

TEST(CalibrateTest, Defaults) {
  json doc = Calibrate();
  for (const char* key : {"loss", "relative_step", "max_iterations", "noise_replicates",
                          "intervals", "line_search"})
    doc.erase(key);
  doc["targets"][0]["by"] = "all";
  doc["targets"][0].erase("variance");
  ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", doc));
  const CalibrationDesign defaults;
  EXPECT_EQ(e.Input<CalibrationDesign>().loss, "huber");
  EXPECT_DOUBLE_EQ(e.Input<CalibrationDesign>().loss_scale, 3.0);
  EXPECT_DOUBLE_EQ(e.Input<CalibrationDesign>().relative_step, 0.05);
  EXPECT_EQ(e.Input<CalibrationDesign>().max_iterations, 30);
  EXPECT_EQ(e.Input<CalibrationDesign>().noise_replicates, 4);
  EXPECT_EQ(e.Input<CalibrationDesign>().intervals, "wald");
  EXPECT_TRUE(e.Input<CalibrationDesign>().line_search);
  EXPECT_EQ(e.Input<CalibrationDesign>().loss, defaults.loss);
  EXPECT_FALSE(e.Input<CalibrationDesign>().stages[0].targets[0].by_operator);
  // A loss without a scale keeps the default scale.
  doc["loss"] = {{"kind", "none"}};
  e = LoadExperiment(WriteJson(TestDir() / "e.json", doc));
  EXPECT_EQ(e.Input<CalibrationDesign>().loss, "none");
  EXPECT_DOUBLE_EQ(e.Input<CalibrationDesign>().loss_scale, 3.0);
}

TEST(CalibrateTest, ShippedExperimentResolvesItsLabRelativeToItself) {
  const ExperimentFile e =
      LoadExperiment(SourcePath("experiments/calibrate_synthetic.json"));
  EXPECT_EQ(e.kind, "calibrate");
  EXPECT_TRUE(
      std::filesystem::equivalent(e.Input<CalibrationDesign>().lab_path,
                                  SourcePath("data/synthetic_block/dataset.json")))
      << e.Input<CalibrationDesign>().lab_path;
  EXPECT_TRUE(std::filesystem::equivalent(
      e.scene_path, SourcePath("experiments/scenes/steel_block_move.json")));
  ASSERT_EQ(e.Input<CalibrationDesign>().stages[0].parameters.size(), 1u);
  EXPECT_EQ(e.Input<CalibrationDesign>().stages[0].parameters[0].name, "guidance/kappa");
  ASSERT_EQ(e.Input<CalibrationDesign>().stages[0].targets.size(), 1u);
  EXPECT_TRUE(e.Input<CalibrationDesign>().stages[0].targets[0].by_operator);
  EXPECT_EQ(e.Input<CalibrationDesign>().loss, "huber");
  EXPECT_EQ(e.trials, 20);
}

TEST(CalibrateErrorsTest, UnknownParameterName) {
  json doc = Calibrate();
  doc["parameters"][1]["name"] = "guidance/kapa";
  ExpectError(doc, "/parameters/1/name", "must be one of: ", "\"guidance/kapa\"");
}

TEST(CalibrateErrorsTest, ChoiceOrIntegerParameter) {
  for (const char* name :
       {"simulation/integrator", "visibility/grid", "visibility/mode"}) {
    SCOPED_TRACE(name);
    json doc = Calibrate();
    doc["parameters"][0] = FitParam(name, 16, 8, 32);
    ExpectError(doc, "/parameters/0/name", "a calibration fits real-valued parameters",
                name);
  }
}

TEST(CalibrateErrorsTest, FittedTwice) {
  json doc = Calibrate();
  doc["parameters"][1] = FitParam("guidance/kappa", 300, 100, 500);
  ExpectError(doc, "/parameters/1/name", "fitted once only (also at /parameters/0)");
}

TEST(CalibrateErrorsTest, LowerNotBelowUpper) {
  json doc = Calibrate();
  doc["parameters"][0] = FitParam("guidance/kappa", 400, 400, 400);
  ExpectError(doc, "/parameters/0/upper", "must exceed lower = 400", "400");
  doc["parameters"][0] = FitParam("guidance/kappa", 400, 500, 300);
  ExpectError(doc, "/parameters/0/upper", "must exceed lower = 500", "300");
}

TEST(CalibrateErrorsTest, StartOutsideTheBounds) {
  json doc = Calibrate();
  doc["parameters"][0] = FitParam("guidance/kappa", 40, 50, 2000);
  ExpectError(doc, "/parameters/0/start", "must lie within [lower, upper] = [50, 2000]",
              "40");
  doc["parameters"][0] = FitParam("guidance/kappa", 2001, 50, 2000);
  ExpectError(doc, "/parameters/0/start", "must lie within [lower, upper] = [50, 2000]",
              "2001");
}

TEST(CalibrateErrorsTest, MissingOrMistypedParameterFields) {
  for (const char* key : {"name", "start", "lower", "upper"}) {
    SCOPED_TRACE(key);
    json doc = Calibrate();
    doc["parameters"][0].erase(key);
    ExpectError(doc, std::string("/parameters/0/") + key,
                std::string("required field '") + key + "' is missing", "(missing)");
  }
  json doc = Calibrate();
  doc["parameters"][0]["lower"] = "50";
  ExpectError(doc, "/parameters/0/lower", "must be a number, not a string");
  doc = Calibrate();
  doc["parameters"][0]["step"] = 0.1;
  ExpectError(doc, "/parameters/0/step", "unknown key 'step'");
  doc = Calibrate();
  doc["parameters"] = json::array();
  ExpectError(doc, "/parameters", "at least 1 element");
  doc.erase("parameters");
  ExpectError(doc, "/parameters", "required field 'parameters' is missing");
}

// A bound must obey the parameter's rule. The fit's differences stay within
// the bounds (calibrate/feasible_difference.h), so a bound on the rule's
// edge is one.
TEST(CalibrateErrorsTest, ABoundMustObeyTheRule) {
  json doc = Calibrate();
  doc["parameters"][1] = FitParam("reach/value_at_d2", 0.5, 0.2, 1.05);
  ExpectError(doc, "/parameters/1/upper",
              "the bound 1.05 breaks reach/value_at_d2's rule: must lie in [0, 1]",
              "1.05");
  doc["parameters"][1] = FitParam("reach/value_at_d2", 0.5, 0.2, 1.0);
  EXPECT_DOUBLE_EQ(LoadExperiment(WriteJson(TestDir() / "e.json", doc))
                       .Input<CalibrationDesign>()
                       .stages[0]
                       .parameters[1]
                       .upper,
                   1.0);
  // A positive parameter's lower bound of 0.
  doc = Calibrate();
  doc["parameters"][0] = FitParam("guidance/kappa", 400, 0, 2000);
  ExpectError(doc, "/parameters/0/lower",
              "breaks guidance/kappa's rule: must lie in (0, 1e6]", "0");
  // An angle's upper bound past 180 degrees; 180 itself is in the table's
  // range, and the fit stays below it by the curve's own rule (the plateau
  // ends before 180), which the valid region holds.
  doc = Calibrate();
  doc["parameters"][1] = FitParam("sight/plateau_to_deg", 60, 45, 181);
  ExpectError(doc, "/parameters/1/upper", "breaks sight/plateau_to_deg's rule");
  doc["parameters"][1] = FitParam("sight/plateau_to_deg", 60, 45, 180);
  EXPECT_NO_THROW(LoadExperiment(WriteJson(TestDir() / "e.json", doc)));
}

TEST(CalibrateErrorsTest, UnknownQuantity) {
  json doc = Calibrate();
  doc["targets"][1]["quantity"] = "assembly_tme";
  ExpectError(doc, "/targets/1/quantity",
              "must be one of: assembly_time, success_rate, eta, lambda_c",
              "\"assembly_tme\"");
}

TEST(CalibrateErrorsTest, PartNotInTheScenesSequence) {
  json doc = Calibrate();
  doc["targets"][0]["part"] = "piston_rod";
  ExpectError(doc, "/targets/0/part", "must be one of: all, block", "\"piston_rod\"");
}

TEST(CalibrateErrorsTest, TargetsShapeAndBy) {
  json doc = Calibrate();
  doc["targets"][0]["by"] = "sex";
  ExpectError(doc, "/targets/0/by", "must be one of: operator, repetition, all",
              "\"sex\"");
  // Variances pool over one target per operator, and only a mean's.
  doc = Calibrate();
  doc["targets"][0]["variance"] = "shared";
  ExpectError(doc, "/targets/0/variance", "must be one of: own, pooled", "\"shared\"");
  doc = Calibrate();
  doc["targets"][0]["by"] = "all";
  ExpectError(doc, "/targets/0/variance", "needs \"by\": \"operator\"", "\"pooled\"");
  doc = Calibrate();
  doc["targets"][0]["quantity"] = "success_rate";
  ExpectError(doc, "/targets/0/variance", "a rate's variance is binomial", "\"pooled\"");
  doc = Calibrate();
  doc["targets"][0]["parts"] = "block";
  ExpectError(doc, "/targets/0/parts", "did you mean 'part'?");
  doc = Calibrate();
  doc["targets"][1].erase("part");
  ExpectError(doc, "/targets/1/part", "required field 'part' is missing");
  doc = Calibrate();
  doc["targets"] = json::array();
  ExpectError(doc, "/targets", "at least 1 element");
}

TEST(CalibrateErrorsTest, LossStepAndIterationsOutOfRange) {
  json doc = Calibrate();
  doc["loss"]["kind"] = "l2";
  ExpectError(doc, "/loss/kind", "must be one of: huber, cauchy, none", "\"l2\"");
  doc = Calibrate();
  doc["loss"]["scale"] = 0;
  ExpectError(doc, "/loss/scale", "must lie in [0.1, 100]", "0");
  doc = Calibrate();
  doc["loss"] = {{"scale", 3}};
  ExpectError(doc, "/loss/kind", "required field 'kind' is missing");
  doc = Calibrate();
  doc["relative_step"] = 0.6;
  ExpectError(doc, "/relative_step", "must lie in [1e-4, 0.5]", "0.6");
  doc = Calibrate();
  doc["max_iterations"] = 0;
  ExpectError(doc, "/max_iterations", "must lie in [1, 1000]", "0");
  doc["max_iterations"] = 2.5;
  ExpectError(doc, "/max_iterations", "must be an integer", "2.5");
  doc = Calibrate();
  doc["noise_replicates"] = 101;
  ExpectError(doc, "/noise_replicates", "must lie in [0, 100]", "101");
  doc = Calibrate();
  doc["intervals"] = "bootstrap";
  ExpectError(doc, "/intervals", "must be one of: wald, profile", "\"bootstrap\"");
  doc = Calibrate();
  doc["line_search"] = "off";
  ExpectError(doc, "/line_search", "must be true or false", "\"off\"");
}

TEST(CalibrateErrorsTest, LabFileMissing) {
  json doc = Calibrate();
  doc["lab"] = "no_such_lab/dataset.json";
  ExpectError(doc, "/lab", "no lab dataset file at", "no_such_lab/dataset.json");
  doc.erase("lab");
  ExpectError(doc, "/lab", "required field 'lab' is missing", "(missing)");
}

TEST(CalibrateErrorsTest, ErrorsNameTheExperimentFileNotTheScene) {
  json doc = Calibrate();
  doc["parameters"][0]["name"] = "visibility/grid";
  const std::string path = WriteJson(TestDir() / "experiment.json", doc);
  try {
    LoadExperiment(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path +
                                         ": /parameters/0/name = \"visibility/grid\": "
                                         "a calibration fits real-valued parameters");
  }
}

// A calibration in stages: each stage its parameters, targets and solver.
json Staged() {
  json doc = Calibrate();
  json first = {{"name", "kappa"},
                {"solver", "golden_section"},
                {"parameters", {FitParam("guidance/kappa", 400, 50, 2000)}},
                {"targets", {{{"quantity", "assembly_time"}, {"part", "block"}}}}};
  json second = {{"name", "hand"},
                 {"parameters", {FitParam("guidance/hand_mass", 1.0, 0.5, 2.0)}},
                 {"targets", {{{"quantity", "success_rate"}, {"part", "all"}}}}};
  doc.erase("parameters");
  doc.erase("targets");
  doc["stages"] = {first, second};
  doc["tolerance"] = 0.08;
  return doc;
}

TEST(CalibrateTest, StagesLoadInOrderWithTheirSolvers) {
  const ExperimentFile e = LoadExperiment(WriteJson(TestDir() / "e.json", Staged()));
  const CalibrationDesign& d = e.Input<CalibrationDesign>();
  ASSERT_EQ(d.stages.size(), 2u);
  EXPECT_EQ(d.stages[0].name, "kappa");
  EXPECT_EQ(d.stages[0].pointer, "/stages/0");
  EXPECT_EQ(d.stages[0].solver, "golden_section");
  EXPECT_EQ(d.stages[0].parameters[0].pointer, "/stages/0/parameters/0");
  EXPECT_EQ(d.stages[1].name, "hand");
  EXPECT_EQ(d.stages[1].solver, "levenberg_marquardt");
  EXPECT_EQ(d.stages[1].targets[0].quantity, "success_rate");
  EXPECT_DOUBLE_EQ(d.tolerance, 0.08);
  // The shipped paper calibration: kappa, then A_max on the fatigue design.
  const ExperimentFile paper =
      LoadExperiment(SourcePath("experiments/calibrate_paper.json"));
  ASSERT_EQ(paper.Input<CalibrationDesign>().stages.size(), 2u);
  EXPECT_EQ(paper.Input<CalibrationDesign>().stages[0].parameters[0].name,
            "guidance/kappa");
  EXPECT_EQ(paper.Input<CalibrationDesign>().stages[1].parameters[0].name,
            "fatigue/a_max");
  EXPECT_EQ(paper.Input<CalibrationDesign>().stages[1].targets[1].segment, 4);
}

TEST(CalibrateErrorsTest, StagesAreWellFormed) {
  json doc = Staged();
  doc["parameters"] = {FitParam("guidance/kappa", 400, 50, 2000)};
  ExpectError(doc, "/parameters",
              "states its parameters, targets and solver in each stage");
  doc = Staged();
  doc["stages"][1]["parameters"][0]["name"] = "guidance/kappa";
  ExpectError(doc, "/stages/1/parameters/0/name",
              "fitted once only (also at "
              "/stages/0/parameters/0)");
  doc = Staged();
  doc["stages"][1]["name"] = "kappa";
  ExpectError(doc, "/stages/1/name", "a stage name is used once");
  doc = Staged();
  doc["stages"][0]["parameters"].push_back(FitParam("guidance/hand_mass", 1.0, 0.5, 2.0));
  ExpectError(doc, "/stages/0/parameters",
              "the golden_section solver fits exactly one parameter");
  doc = Staged();
  doc["stages"][0]["solver"] = "newton";
  ExpectError(doc, "/stages/0/solver", "must be one of", "newton");
  doc = Staged();
  doc["stages"][1].erase("name");
  ExpectError(doc, "/stages/1/name", "required field 'name' is missing");
  doc = Staged();
  doc["tolerance"] = 0.9;
  ExpectError(doc, "/tolerance", "", "0.9");
  // Segment and non-segment targets may share a stage (both designs run) and
  // a file.
  doc = Staged();
  doc["fatigue"] = {{"duration_min", 60}, {"segments", 4}};
  doc["stages"][1]["targets"] = {
      {{"quantity", "success_rate"}, {"part", "all"}, {"segment", 4}}};
  EXPECT_NO_THROW(LoadExperiment(WriteJson(TestDir() / "e.json", doc)));
  doc["stages"][1]["targets"].push_back({{"quantity", "success_rate"}, {"part", "all"}});
  EXPECT_EQ(LoadExperiment(WriteJson(TestDir() / "e.json", doc))
                .Input<CalibrationDesign>()
                .stages[1]
                .targets.size(),
            2u);
  // A stage's segment beyond the fatigue design's.
  doc["stages"][1]["targets"] = {
      {{"quantity", "success_rate"}, {"part", "all"}, {"segment", 5}}};
  ExpectError(doc, "/stages/1/targets/0/segment", "the fatigue design has 4 segments",
              "5");
  // "stages" belongs to calibrate only.
  json table = Experiment("table1");
  table["stages"] = json::array();
  ExpectError(table, "/stages", "only an experiment of kind \"calibrate\"");
}

// ---------------------------------------------------------------------------
// Comparisons (compare).

// A comparison against the paper's numbers: quantities of segments and
// conditions beside one without, and the hour of work they read.
json ComparePaper() {
  json e = Experiment("compare");
  e["lab"] = SourcePath("data/paper/dataset.json");
  e["fatigue"] = {{"duration_min", 60}, {"segments", 4}, {"pilot_cycles", 3}};
  e["quantities"] = {{{"quantity", "assembly_time"}, {"part", "all"}, {"margin", 1}},
                     {{"quantity", "assembly_time"},
                      {"part", "all"},
                      {"condition", "virtual"},
                      {"margin", 1.5}},
                     {{"quantity", "success_rate"},
                      {"part", "all"},
                      {"segment", 4},
                      {"condition", "real"},
                      {"margin", 0.1}}};
  return e;
}

TEST(CompareTest, SegmentsAndConditionsLoadWithTheFatigueDesign) {
  const ExperimentFile e =
      LoadExperiment(WriteJson(TestDir() / "e.json", ComparePaper()));
  EXPECT_EQ(e.kind, "compare");
  const ComparisonDesign& d = e.Input<ComparisonDesign>();
  EXPECT_TRUE(
      std::filesystem::equivalent(d.lab_path, SourcePath("data/paper/dataset.json")));
  ASSERT_EQ(d.quantities.size(), 3u);
  EXPECT_EQ(d.quantities[0].segment, 0);
  EXPECT_EQ(d.quantities[0].condition, "");  // any
  EXPECT_DOUBLE_EQ(d.quantities[0].margin, 1.0);
  EXPECT_EQ(d.quantities[1].condition, "virtual");
  EXPECT_DOUBLE_EQ(d.quantities[1].margin, 1.5);
  EXPECT_EQ(d.quantities[2].quantity, "success_rate");
  EXPECT_EQ(d.quantities[2].segment, 4);
  EXPECT_EQ(d.quantities[2].condition, "real");
  EXPECT_EQ(d.quantities[2].pointer, "/quantities/2");
  EXPECT_DOUBLE_EQ(d.fatigue.duration_min, 60);
  EXPECT_EQ(d.fatigue.segments, 4);
  EXPECT_EQ(d.fatigue.pilot_cycles, 3);
}

TEST(CompareTest, ShippedPaperComparison) {
  const ExperimentFile e = LoadExperiment(SourcePath("experiments/compare_paper.json"));
  EXPECT_EQ(e.scene.name, "hydraulic_cylinder");
  const ComparisonDesign& d = e.Input<ComparisonDesign>();
  ASSERT_EQ(d.quantities.size(), 6u);
  EXPECT_EQ(d.quantities[0].condition, "virtual");
  EXPECT_EQ(d.quantities[1].condition, "");
  EXPECT_EQ(d.quantities[5].segment, 4);
  EXPECT_EQ(d.quantities[5].condition, "virtual");
  EXPECT_EQ(d.fatigue.segments, 4);
  EXPECT_EQ(d.fatigue.pilot_cycles, 4);
}

TEST(CompareErrorsTest, BadSegmentsAndConditions) {
  json doc = ComparePaper();
  doc["quantities"][2]["segment"] = 5;  // the hour has 4
  ExpectError(doc, "/quantities/2/segment", "the fatigue design has 4 segments", "5");
  doc = ComparePaper();
  doc.erase("fatigue");  // the default hour has 4 segments too
  doc["quantities"][2]["segment"] = 7;
  ExpectError(doc, "/quantities/2/segment", "the fatigue design has 4 segments", "7");
  doc = ComparePaper();
  doc["quantities"][2]["segment"] = 0;
  ExpectError(doc, "/quantities/2/segment", "must lie in [1, 1000]", "0");
  doc["quantities"][2]["segment"] = 1.5;
  ExpectError(doc, "/quantities/2/segment", "must be an integer", "1.5");
  doc = ComparePaper();
  doc["quantities"][2]["by"] = "operator";
  ExpectError(doc, "/quantities/2/by",
              "a segment's value is the lab's over all operators");
  doc = ComparePaper();
  doc["quantities"][2]["by"] = "repetition";
  ExpectError(doc, "/quantities/2/by", "which has no repetitions");
  doc = ComparePaper();
  doc["quantities"][1]["condition"] = "";
  ExpectError(doc, "/quantities/1/condition", "leave the key out to read any");
  doc["quantities"][1]["condition"] = 3;
  ExpectError(doc, "/quantities/1/condition", "must be a string");
  doc = ComparePaper();
  doc["quantities"][2]["segmnt"] = 1;
  ExpectError(doc, "/quantities/2/segmnt", "did you mean 'segment'?");
  doc = ComparePaper();
  doc["quantities"][2].erase("margin");
  ExpectError(doc, "/quantities/2/margin", "required field 'margin' is missing");
  doc = ComparePaper();
  doc["fatigue"]["segments"] = 0;
  ExpectError(doc, "/fatigue/segments", "must lie in [1, 1000]", "0");
}

TEST(FormatOfTest, NamesEveryVahfFormat) {
  const std::vector<std::pair<std::string, std::string>> files = {
      {"experiments/scenes/steel_block_move.json", "scene"},
      {"experiments/calibrate_synthetic.json", "experiment"},
      {"data/synthetic_block/dataset.json", "lab"},
      {"data/synthetic_block/generator.json", "synthetic"}};
  for (const auto& [file, format] : files)
    EXPECT_EQ(FileFormatOf(SourcePath(file)), format);
  EXPECT_EQ(FormatOf({{"format", "vahf-overrides/1"}, {"parameters", json::object()}},
                     "o.json"),
            "overrides");
  try {
    FormatOf({{"format", "vahf-override/1"}}, "o.json");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "o.json");
    EXPECT_EQ(e.where(), "/format");
    EXPECT_THAT(e.rule(), HasSubstr("\"vahf-overrides/1\""));
    EXPECT_THAT(e.rule(), HasSubstr("\"vahf-synthetic/1\""));
  }
}

// ---------------------------------------------------------------------------
// A key that only another kind reads is an error naming the key and the kind.

struct WrongKindCase {
  const char* key;
  json value;
  const char* reader;  // the kind that reads it
};

TEST(WrongKindTest, EachKeyWithEachOtherKind) {
  const std::vector<WrongKindCase> cases = {
      {"operators", json::array({Operator("x", "male", 1.7, 0.7)}), "assembly_time"},
      {"conditions", json::array({{{"name", "g"}, {"scene", CylinderScene()}}}),
       "human_factors_groups"},
      {"instants_s", json::array({3, 6}), "human_factors_groups"},
      {"paper_cycle_s", 16, "human_factors_groups"},
      {"fatigue", {{"segments", 4}}, "fatigue"},
      {"paper_table", SourcePath("reference/paper/table1.json"), "table1"},
      {"experiments", json::array({SourcePath("experiments/table1.json")}), "paper"},
      {"scenes", json::array({CylinderScene()}), "precision"},
      {"reference", {{"simulation/accuracy", 1e-8}}, "precision"},
      {"settings", json::array({{{"simulation/accuracy", 1e-3}}}), "precision"},
      {"noise_trials", 12, "precision"},
      {"parameters", json::array({FitParam("guidance/kappa", 400, 50, 2000)}),
       "calibrate"},
      {"targets", json::array({{{"quantity", "assembly_time"}, {"part", "all"}}}),
       "calibrate"},
      {"loss", {{"kind", "huber"}}, "calibrate"},
      {"relative_step", 0.05, "calibrate"},
      {"max_iterations", 30, "calibrate"},
  };
  const std::vector<std::string> kinds = {
      "table1",    "assembly_time", "human_factors_groups", "fatigue", "paper",
      "precision", "calibrate"};
  for (const WrongKindCase& c : cases) {
    for (const std::string& kind : kinds) {
      if (kind == c.reader) continue;
      // A calibration reads the fatigue design its segment targets need.
      if (kind == "calibrate" && std::string(c.key) == "fatigue") continue;
      SCOPED_TRACE(std::string(c.key) + " in a " + kind + " experiment");
      json doc;
      if (kind == "paper") {
        doc = Paper({SourcePath("experiments/table1.json")});
      } else if (kind == "precision") {
        doc = Precision();
      } else if (kind == "calibrate") {
        doc = Calibrate();
      } else if (kind == "human_factors_groups") {
        doc = HumanFactorsGroups();
      } else {
        doc = Experiment(kind);
      }
      doc[c.key] = c.value;
      ExpectError(doc, std::string("/") + c.key,
                  std::string("only an experiment of kind \"") + c.reader + "\"");
      ExpectError(doc, std::string("/") + c.key, std::string("reads \"") + c.key + "\"");
    }
  }
}

// "lab" is read by calibrate (and by compare, when that kind exists).
TEST(WrongKindTest, LabInAnotherKindsFile) {
  for (const std::string kind : {"table1", "assembly_time", "human_factors_groups",
                                 "fatigue", "paper", "precision"}) {
    SCOPED_TRACE(kind);
    json doc = kind == "paper"       ? Paper({SourcePath("experiments/table1.json")})
               : kind == "precision" ? Precision()
               : kind == "human_factors_groups" ? HumanFactorsGroups()
                                                : Experiment(kind);
    doc["lab"] = SourcePath("data/synthetic_block/dataset.json");
    ExpectError(doc, "/lab", "only an experiment of kind \"calibrate\"");
    ExpectError(doc, "/lab", "reads \"lab\"");
  }
}

TEST(WrongKindTest, WhatReadsFileWhereValueRule) {
  json doc = Table1();
  doc["fatigue"] = {{"segments", 4}};
  const std::string path = WriteJson(TestDir() / "experiment.json", doc);
  try {
    LoadExperiment(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        path +
            ": /fatigue = {\"segments\":4}: only an experiment of kind \"fatigue\", "
            "\"calibrate\" or \"compare\" reads \"fatigue\"");
  }
}

TEST(WrongKindTest, AKeyNoKindReadsIsUnknown) {
  json doc = AssemblyTime();
  doc["operator"] = doc["operators"];
  ExpectError(doc, "/operator", "did you mean 'operators'?");
}

// A paper file's "handbooks" names existing tables: a missing one is an
// InputError at its key.
TEST(PaperHandbooksTest, AMissingTableIsAnInputErrorAtItsKey) {
  json doc = Paper({SourcePath("experiments/table1.json")});
  doc["handbooks"] = {{"boothroyd_dewhurst", "no_such.csv"},
                      {"mtm1_position", SourcePath("data/handbooks/mtm1_position.csv")}};
  ExpectError(doc, "/handbooks/boothroyd_dewhurst",
              "no Boothroyd-Dewhurst insertion table file at");
}

}  // namespace
}  // namespace vahf::scene
