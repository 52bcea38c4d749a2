// Tests of parameter-override files (scene/overrides.h, docs/calibration.md
// "The loop"): LoadOverrides reads a good file and refuses every malformed one
// with an InputError naming the file, the JSON pointer and the rule;
// ApplyOverrides sets the values in a scene and checks the rules that tie
// parameters together (naming the override file), and on an experiment file
// reaches every scene it runs: its scene, its working conditions' scenes, a
// precision experiment's scenes, reference and settings (a setting keeps the
// values it sets itself), each experiment a paper run lists, and the
// operators an assembly_time experiment lists; it records the file in
// overrides_path.
#include "vahf/scene/overrides.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include "support/test_files.h"
#include "vahf/calibrate/calibration_input.h"
#include "vahf/core/error.h"
#include "vahf/experiment/groups_input.h"
#include "vahf/experiment/precision_input.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/paper_input.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::scene {

using experiment::ConditionEntry;
using experiment::GroupsInput;
using experiment::PrecisionDesign;
using experiment::PrecisionScene;
using kinds::PaperInput;

using kinds::LoadExperiment;
using kinds::ParseExperiment;
namespace {

using ::nlohmann::json;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::Lower;
using ::testing::Pair;
using testing::WriteFile;

std::string SourcePath(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

std::filesystem::path TestDir() { return testing::TestDir("vahf_overrides_test"); }

std::string WriteJson(const std::filesystem::path& path, const json& doc) {
  return WriteFile(path, doc.dump(1));
}

json Overrides(const json& parameters) {
  return {{"format", "vahf-overrides/1"},
          {"source", "overrides_test"},
          {"parameters", parameters}};
}

// Writes `parameters` as an override file in the running test's directory and loads it.
ParameterOverrides Load(const json& parameters) {
  return LoadOverrides(WriteJson(TestDir() / "overrides.json", Overrides(parameters)));
}

// Writes `doc` to DIR/overrides.json and expects LoadOverrides to throw an
// InputError naming that file at `where`, whose rule contains `rule` and,
// unless `value` is empty, whose value contains `value` (ignoring case).
void ExpectError(const json& doc, const std::string& where, const std::string& rule,
                 const std::string& value = "") {
  const std::string path = WriteJson(TestDir() / "overrides.json", doc);
  try {
    LoadOverrides(path);
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

Scene SteelBlock() {
  return LoadScene(SourcePath("experiments/scenes/steel_block_move.json"));
}

// ---------------------------------------------------------------------------
// LoadOverrides.

TEST(LoadOverridesTest, ReadsAGoodFile) {
  const std::string path =
      WriteJson(TestDir() / "good.json", {{"format", "vahf-overrides/1"},
                                          {"source", "a calibration"},
                                          {"parameters",
                                           {{"guidance/kappa", 251.5},
                                            {"simulation/integrator", "CPodes"},
                                            {"visibility/grid", 16}}}});
  const ParameterOverrides o = LoadOverrides(path);
  EXPECT_EQ(o.file, path);
  EXPECT_EQ(o.source, "a calibration");
  EXPECT_THAT(o.values, ::testing::UnorderedElementsAre(
                            Pair("guidance/kappa", json(251.5)),
                            Pair("simulation/integrator", json("CPodes")),
                            Pair("visibility/grid", json(16))));
}

TEST(LoadOverridesTest, SourceIsOptional) {
  json doc = Overrides({{"guidance/kappa", 300}});
  doc.erase("source");
  const ParameterOverrides o = LoadOverrides(WriteJson(TestDir() / "o.json", doc));
  EXPECT_TRUE(o.source.empty());
  EXPECT_THAT(o.values, ElementsAre(Pair("guidance/kappa", json(300))));
}

TEST(LoadOverridesErrorsTest, WrongFormatString) {
  json doc = Overrides({{"guidance/kappa", 300}});
  doc["format"] = "vahf-experiment/1";
  ExpectError(doc, "/format",
              "an override file declares \"format\": \"vahf-overrides/1\"",
              "vahf-experiment/1");
  doc.erase("format");
  ExpectError(doc, "/format", "required field 'format' is missing", "(missing)");
}

TEST(LoadOverridesErrorsTest, UnknownParameterName) {
  ExpectError(Overrides({{"guidance/kappa", 300}, {"guidance/kapa", 1}}),
              "/parameters/guidance~1kapa",
              "unknown key 'guidance/kapa' (did you mean 'guidance/kappa'?)");
  ExpectError(Overrides({{"kappa", 300}}), "/parameters/kappa", "unknown key 'kappa'");
}

TEST(LoadOverridesErrorsTest, ValueBreaksItsParametersRule) {
  ExpectError(Overrides({{"guidance/kappa", -1}}), "/parameters/guidance~1kappa",
              "must lie in (0, 1e6]", "-1");
  ExpectError(Overrides({{"reach/value_at_d2", 1.5}}), "/parameters/reach~1value_at_d2",
              "must lie in [0, 1]", "1.5");
  ExpectError(Overrides({{"visibility/grid", 2.5}}), "/parameters/visibility~1grid",
              "must be an integer", "2.5");
  ExpectError(Overrides({{"simulation/integrator", "Euler"}}),
              "/parameters/simulation~1integrator", "must be one of", "\"Euler\"");
  ExpectError(Overrides({{"guidance/kappa", "250"}}), "/parameters/guidance~1kappa",
              "must be a number, not a string");
}

TEST(LoadOverridesErrorsTest, EmptyParameters) {
  ExpectError(Overrides(json::object()), "/parameters", "names at least one parameter");
  json doc = Overrides({{"guidance/kappa", 300}});
  doc.erase("parameters");
  ExpectError(doc, "/parameters", "required field 'parameters' is missing");
  doc["parameters"] = json::array({300});
  ExpectError(doc, "/parameters", "must be an object, not a array");
}

TEST(LoadOverridesErrorsTest, UnknownTopLevelKey) {
  json doc = Overrides({{"guidance/kappa", 300}});
  doc["sources"] = "typo";
  ExpectError(doc, "/sources", "unknown key 'sources' (did you mean 'source'?)", "typo");
}

TEST(LoadOverridesErrorsTest, NotAnObject) {
  ExpectError(json::array({Overrides({{"guidance/kappa", 300}})}), "/",
              "an override file is a JSON object");
  ExpectError(json(250), "/", "an override file is a JSON object", "250");
}

TEST(LoadOverridesErrorsTest, WholeMessageNamesFilePointerValueAndRule) {
  const std::string path =
      WriteJson(TestDir() / "overrides.json", Overrides({{"guidance/kappa", -1}}));
  try {
    LoadOverrides(path);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ": /parameters/guidance~1kappa = -1: must lie in (0, 1e6]");
  }
}

// ---------------------------------------------------------------------------
// ApplyOverrides on a scene.

TEST(ApplyOverridesSceneTest, SetsTheValues) {
  Scene scene = SteelBlock();
  ASSERT_NE(scene.params.guidance.kappa, 321.0);
  ASSERT_NE(scene.params.visibility.grid, 24);
  const double accuracy = scene.params.simulation.accuracy;
  ApplyOverrides(Load({{"guidance/kappa", 321},
                       {"visibility/grid", 24},
                       {"simulation/integrator", "CPodes"}}),
                 &scene);
  EXPECT_DOUBLE_EQ(scene.params.guidance.kappa, 321.0);
  EXPECT_EQ(scene.params.visibility.grid, 24);
  EXPECT_EQ(scene.params.simulation.integrator, "CPodes");
  // What the file does not name keeps the scene's value.
  EXPECT_DOUBLE_EQ(scene.params.simulation.accuracy, accuracy);
  EXPECT_DOUBLE_EQ(scene.params.guidance.vision_sigma_depth, 0.002);
}

// The steel block's operator (height 1.70 m, arm 0.72 m): D1 = 1.0 * 0.72 m
// exceeds D2 = 0.39 * 1.70 m = 0.663 m.
TEST(ApplyOverridesSceneTest, CrossParameterRuleNamesTheOverrideFile) {
  Scene scene = SteelBlock();
  const ParameterOverrides o = Load({{"reach/d1_arm_fraction", 1.0}});
  try {
    ApplyOverrides(o, &scene);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), o.file) << e.what();
    EXPECT_EQ(e.where(), "/parameters") << e.what();
    EXPECT_THAT(e.value(), HasSubstr("steel_block_move")) << e.what();
    EXPECT_THAT(e.rule(), HasSubstr("reach breakpoints must increase for this operator"))
        << e.what();
  }
  // The sight plateau's order too.
  Scene again = SteelBlock();
  const ParameterOverrides sight = Load({{"sight/plateau_from_deg", 50}});
  try {
    ApplyOverrides(sight, &again);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), sight.file) << e.what();
    EXPECT_THAT(e.rule(), HasSubstr("plateau_from_deg (50)")) << e.what();
  }
}

// ---------------------------------------------------------------------------
// ApplyOverrides on an experiment file.

TEST(ApplyOverridesExperimentTest, SetsTheSceneAndRecordsTheFile) {
  ExperimentFile e = LoadExperiment(SourcePath("experiments/table1.json"));
  EXPECT_TRUE(e.overrides_path.empty());
  const ParameterOverrides o = Load({{"guidance/kappa", 321}});
  ApplyOverrides(o, &e);
  EXPECT_EQ(e.overrides_path, o.file);
  EXPECT_DOUBLE_EQ(e.scene.params.guidance.kappa, 321.0);
}

// A calibration: a fitted parameter's override is its start (its scene
// keeps its own value, which the first stage fitting it replaces); another
// parameter's sets the scene; a start outside the stage's bounds is refused,
// naming the override file and the bounds.
TEST(ApplyOverridesExperimentTest, ACalibrationStartsAtItsFittedParametersOverrides) {
  ExperimentFile e = LoadExperiment(SourcePath("experiments/calibrate_paper.json"));
  const double kappa = e.scene.params.guidance.kappa;
  const ParameterOverrides o = Load({{"guidance/kappa", 22.5},
                                     {"fatigue/a_max", 30000},
                                     {"guidance/damping_ratio", 0.75}});
  ApplyOverrides(o, &e);
  EXPECT_EQ(e.scene.params.guidance.kappa, kappa);
  EXPECT_EQ(e.scene.params.guidance.damping_ratio, 0.75);
  const auto& design = e.Input<calibrate::CalibrationDesign>();
  ASSERT_EQ(design.stages.size(), 2u);
  EXPECT_EQ(design.stages[0].parameters[0].start, 22.5);
  EXPECT_EQ(design.stages[0].parameters[0].start_from, o.file);
  EXPECT_EQ(design.stages[1].parameters[0].start, 30000);
  EXPECT_EQ(design.OwnParameters(),
            (std::vector<std::string>{"guidance/kappa", "fatigue/a_max"}));
  ExperimentFile again = LoadExperiment(SourcePath("experiments/calibrate_paper.json"));
  const ParameterOverrides outside = Load({{"guidance/kappa", 500}});
  try {
    ApplyOverrides(outside, &again);
    FAIL() << "no InputError";
  } catch (const InputError& err) {
    EXPECT_EQ(err.file(), outside.file) << err.what();
    EXPECT_EQ(err.where(), "/parameters/guidance~1kappa") << err.what();
    EXPECT_THAT(err.rule(), HasSubstr("must lie within its bounds [1, 400]"))
        << err.what();
  }
}

TEST(ApplyOverridesExperimentTest, CrossParameterRuleNamesTheOverrideFile) {
  ExperimentFile e = LoadExperiment(SourcePath("experiments/table1.json"));
  // The cylinder's operator (1.75 m, arm 0.74 m): D1 = 0.74 m > D2 = 0.6825 m.
  const ParameterOverrides o = Load({{"reach/d1_arm_fraction", 1.0}});
  try {
    ApplyOverrides(o, &e);
    FAIL() << "no InputError";
  } catch (const InputError& err) {
    EXPECT_EQ(err.file(), o.file) << err.what();
    EXPECT_THAT(err.value(), HasSubstr("hydraulic_cylinder")) << err.what();
    EXPECT_THAT(err.rule(), HasSubstr("reach breakpoints must increase")) << err.what();
  }
}

// assembly_time runs the scene once per listed operator: an override must
// keep D1 < D2 < D3 for each of them, as loading the experiment checks. With
// d1_arm_fraction 0.9 the cylinder's own operator is fine (D1 = 0.666 m <
// D2 = 0.6825 m) but the P50 man of experiments/assembly_time.json, the
// first listed to break it, is not (D1 = 0.9 * 0.733 m = 0.660 m > D2 =
// 0.39 * 1.678 m = 0.654 m). Without the check `vahf run --overrides` aborts
// with an internal error when it builds his reach curve.
TEST(ApplyOverridesExperimentTest, ReachRuleIsCheckedForEveryListedOperator) {
  ExperimentFile e = LoadExperiment(SourcePath("experiments/assembly_time.json"));
  const ParameterOverrides o = Load({{"reach/d1_arm_fraction", 0.9}});
  Scene alone = e.scene;
  ApplyOverrides(o, &alone);  // the scene's own operator is within the rule
  try {
    ApplyOverrides(o, &e);
    FAIL() << "no InputError: a run would abort when it builds male P50's reach curve";
  } catch (const InputError& err) {
    EXPECT_EQ(err.file(), o.file) << err.what();
    EXPECT_EQ(err.where(), "/parameters") << err.what();
    EXPECT_THAT(err.value(), HasSubstr("operator 'male P50'")) << err.what();
    EXPECT_THAT(err.value(), HasSubstr("assembly_time.json")) << err.what();
    EXPECT_THAT(err.rule(), HasSubstr("reach breakpoints must increase")) << err.what();
  }
}

TEST(ApplyOverridesExperimentTest, ReachesEveryConditionsScene) {
  ExperimentFile e = LoadExperiment(SourcePath("experiments/human_factors_groups.json"));
  ASSERT_EQ(e.Input<GroupsInput>().conditions.size(), 3u);
  ApplyOverrides(Load({{"guidance/kappa", 321}}), &e);
  for (const ConditionEntry& c : e.Input<GroupsInput>().conditions)
    EXPECT_DOUBLE_EQ(c.scene.params.guidance.kappa, 321.0) << c.name;
}

// A small precision experiment: one scene, a reference and settings, some of
// which set simulation/accuracy themselves.
json SmallPrecision() {
  const json accuracy = {{"simulation/integrator", "RungeKuttaMerson"},
                         {"simulation/accuracy", 1e-3}};
  return {
      {"format", "vahf-experiment/1"},
      {"name", "small_precision"},
      {"kind", "precision"},
      {"seed", 3},
      {"trials", 2},
      {"scenes", {SourcePath("experiments/scenes/peg_in_hole.json")}},
      {"reference",
       {{"simulation/integrator", "RungeKuttaMerson"}, {"simulation/accuracy", 1e-8}}},
      {"settings",
       {accuracy, {{"visibility/grid", 16}}, {{"simulation/accuracy", 1e-5}}}}};
}

TEST(ApplyOverridesPrecisionTest, ASettingKeepsWhatItSetsItself) {
  ExperimentFile e =
      LoadExperiment(WriteJson(TestDir() / "precision.json", SmallPrecision()));
  ASSERT_EQ(e.Input<PrecisionDesign>().scenes.size(), 1u);
  ASSERT_EQ(e.Input<PrecisionDesign>().scenes[0].settings.size(), 3u);
  const ParameterOverrides o =
      Load({{"guidance/kappa", 321}, {"simulation/accuracy", 2e-4}});
  ApplyOverrides(o, &e);
  EXPECT_EQ(e.overrides_path, o.file);
  const PrecisionScene& ps = e.Input<PrecisionDesign>().scenes[0];
  // The scene as its file gives it, and the manifest's scene, get both values.
  EXPECT_DOUBLE_EQ(ps.scene.params.guidance.kappa, 321.0);
  EXPECT_DOUBLE_EQ(ps.scene.params.simulation.accuracy, 2e-4);
  EXPECT_DOUBLE_EQ(e.scene.params.guidance.kappa, 321.0);
  // The reference and every setting get kappa ...
  EXPECT_DOUBLE_EQ(ps.reference.params.guidance.kappa, 321.0);
  for (const Scene& s : ps.settings) EXPECT_DOUBLE_EQ(s.params.guidance.kappa, 321.0);
  // ... but keep the accuracy each sets itself: that is what the experiment varies.
  EXPECT_DOUBLE_EQ(ps.reference.params.simulation.accuracy, 1e-8);
  EXPECT_DOUBLE_EQ(ps.settings[0].params.simulation.accuracy, 1e-3);
  EXPECT_DOUBLE_EQ(ps.settings[2].params.simulation.accuracy, 1e-5);
  // The grid setting does not set the accuracy: the override's.
  EXPECT_EQ(ps.settings[1].params.visibility.grid, 16);
  EXPECT_DOUBLE_EQ(ps.settings[1].params.simulation.accuracy, 2e-4);
}

TEST(ApplyOverridesPrecisionTest, ReachesTheShippedExperimentsReferenceAndSettings) {
  ExperimentFile e = LoadExperiment(SourcePath("experiments/precision.json"));
  ASSERT_EQ(e.Input<PrecisionDesign>().scenes.size(), 2u);
  ApplyOverrides(Load({{"guidance/kappa", 321}, {"simulation/accuracy", 2e-4}}), &e);
  for (const PrecisionScene& ps : e.Input<PrecisionDesign>().scenes) {
    SCOPED_TRACE(ps.scene.name);
    EXPECT_DOUBLE_EQ(ps.scene.params.guidance.kappa, 321.0);
    EXPECT_DOUBLE_EQ(ps.reference.params.guidance.kappa, 321.0);
    EXPECT_DOUBLE_EQ(ps.reference.params.simulation.accuracy, 1e-8);
    ASSERT_EQ(ps.settings.size(), e.Input<PrecisionDesign>().settings.size());
    for (std::size_t k = 0; k < ps.settings.size(); ++k) {
      SCOPED_TRACE(e.Input<PrecisionDesign>().settings[k].label);
      EXPECT_DOUBLE_EQ(ps.settings[k].params.guidance.kappa, 321.0);
      bool own = false;  // does the setting set the accuracy itself?
      for (const auto& [name, value] : e.Input<PrecisionDesign>().settings[k].overrides) {
        if (name == "simulation/accuracy") {
          own = true;
          EXPECT_DOUBLE_EQ(ps.settings[k].params.simulation.accuracy,
                           value.get<double>());
        }
      }
      if (!own) {
        EXPECT_DOUBLE_EQ(ps.settings[k].params.simulation.accuracy, 2e-4);
      }
    }
  }
}

// A value the rules reject in a setting's scene (the peg's operator, 1.75 m
// with arm 0.74 m: D1 = 0.74 m > D2 = 0.6825 m) names the override file.
TEST(ApplyOverridesPrecisionTest, CrossParameterRuleNamesTheOverrideFile) {
  ExperimentFile e =
      LoadExperiment(WriteJson(TestDir() / "precision.json", SmallPrecision()));
  const ParameterOverrides o = Load({{"reach/d1_arm_fraction", 1.0}});
  try {
    ApplyOverrides(o, &e);
    FAIL() << "no InputError";
  } catch (const InputError& err) {
    EXPECT_EQ(err.file(), o.file) << err.what();
    EXPECT_THAT(err.rule(), HasSubstr("reach breakpoints must increase")) << err.what();
  }
}

TEST(ApplyOverridesPaperTest, EveryChildsSceneGetsTheValue) {
  ExperimentFile e = LoadExperiment(SourcePath("experiments/paper.json"));
  ASSERT_EQ(e.Input<PaperInput>().experiments.size(), 4u);
  const ParameterOverrides o = Load({{"guidance/kappa", 321}});
  ApplyOverrides(o, &e);
  EXPECT_EQ(e.overrides_path, o.file);
  for (const ExperimentFile& sub : e.Input<PaperInput>().experiments) {
    SCOPED_TRACE(sub.name);
    EXPECT_EQ(sub.overrides_path, o.file);
    EXPECT_DOUBLE_EQ(sub.scene.params.guidance.kappa, 321.0);
    if (sub.kind != "human_factors_groups") continue;
    for (const ConditionEntry& c : sub.Input<GroupsInput>().conditions)
      EXPECT_DOUBLE_EQ(c.scene.params.guidance.kappa, 321.0) << c.name;
  }
}

// The paper run's assembly_time experiment checks its operators too.
TEST(ApplyOverridesPaperTest, ReachRuleIsCheckedForTheListedOperators) {
  ExperimentFile e = LoadExperiment(SourcePath("experiments/paper.json"));
  const ParameterOverrides o = Load({{"reach/d1_arm_fraction", 0.9}});
  try {
    ApplyOverrides(o, &e);
    FAIL() << "no InputError";
  } catch (const InputError& err) {
    EXPECT_EQ(err.file(), o.file) << err.what();
    EXPECT_THAT(err.value(), HasSubstr("operator 'male P50'")) << err.what();
  }
}

}  // namespace
}  // namespace vahf::scene
