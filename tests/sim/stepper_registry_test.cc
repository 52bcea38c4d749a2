// The steppers' registry (stepper_registry.h): one list of names, which the
// parameter table offers (and `vahf params` describes); no name twice; each
// entry's factory is the kind its needs name; the scene rule accepts every
// name and refuses another with the registry's names; and every stepper runs a
// short free fall. The command line's choices: tests/tools/cli_test.sh.
#include "vahf/sim/stepper_registry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "support/free_fall.h"
#include "vahf/core/error.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"
#include "vahf/scene/stepper_catalogue.h"
#include "vahf/sim/trial.h"

namespace vahf::sim {
namespace {

using ::testing::HasSubstr;

constexpr double kG = 9.80665;

std::vector<std::string> RegistryNames() {
  std::vector<std::string> names;
  for (const StepperEntry& s : Steppers()) names.emplace_back(s.name);
  return names;
}

// The free fall for 0.2 s under `integrator`.
scene::Scene FreeFall(const std::string& integrator) {
  return scene::ParseScene(testing::FreeFallScene({{"time_limit", 0.2},
                                                   {"decision_interval", 0.05},
                                                   {"integrator", integrator},
                                                   {"accuracy", 1e-8},
                                                   {"fixed_step", 1e-3}}),
                           "fall.json");
}

TEST(StepperRegistry, IsTheOneListOfNames) {
  const scene::ParamSpec* rule = scene::FindParam("simulation/integrator");
  ASSERT_NE(rule, nullptr);
  EXPECT_EQ(rule->choices, RegistryNames());
  EXPECT_EQ(scene::StepperNames(), RegistryNames());
  ASSERT_EQ(scene::StepperCatalogue().size(), Steppers().size());
  for (std::size_t k = 0; k < Steppers().size(); ++k) {
    EXPECT_STREQ(scene::StepperCatalogue()[k].description, Steppers()[k].description);
    EXPECT_EQ(scene::StepperCatalogue()[k].needs, Steppers()[k].needs);
  }
  EXPECT_EQ(Steppers().front().name, std::string("RungeKuttaMerson"));  // the default
  EXPECT_EQ(scene::SimulationParams().integrator, Steppers().front().name);
}

TEST(StepperRegistry, ListsNoNameTwice) {
  std::set<std::string> seen;
  for (const StepperEntry& s : Steppers())
    EXPECT_TRUE(seen.insert(s.name).second) << s.name;
}

TEST(StepperRegistry, EachEntryHasTheFactoryItsNeedsName) {
  for (const StepperEntry& s : Steppers()) {
    SCOPED_TRACE(s.name);
    EXPECT_FALSE(std::string(s.description).empty());
    const bool simbody = s.needs == scene::StepperNeeds::kSimbodySystem;
    EXPECT_EQ(s.make_integrator != nullptr, simbody);
    EXPECT_EQ(s.make_core != nullptr, !simbody);
    EXPECT_EQ(&FindStepper(s.name), &s);
  }
}

TEST(StepperRegistry, VahfParamsDescribesEachStepper) {
  const std::string table = scene::ParameterTableMarkdown();
  for (const StepperEntry& s : Steppers())
    EXPECT_THAT(table, HasSubstr(std::string(s.name) + ": " + s.description));
}

TEST(StepperRegistry, TheSceneRuleAcceptsEveryName) {
  for (const StepperEntry& s : Steppers()) {
    SCOPED_TRACE(s.name);
    const scene::Scene scene = FreeFall(s.name);
    EXPECT_EQ(scene.params.simulation.integrator, s.name);
  }
}

TEST(StepperRegistry, TheSceneRuleRefusesAnotherNameWithTheRegistrysNames) {
  std::string names;
  for (const std::string& n : RegistryNames()) names += (names.empty() ? "" : ", ") + n;
  try {
    FreeFall("Euler");
    ADD_FAILURE() << "an unknown integrator was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/parameters/simulation/integrator") << e.what();
    EXPECT_EQ(e.rule(), "must be one of: " + names) << e.what();
    EXPECT_EQ(e.value(), "\"Euler\"") << e.what();
  }
}

// Each factory runs: the block falls as s = g t^2 / 2, its speed to 1 um/s and
// its height to 1 um, but SemiExplicitEuler2's to 0.1 mm (first order in the
// position: at accuracy 1e-8 it lags 12 um more every 0.05 s) and
// MoreauJean's to 0.2 mm (backward Euler's positions at its default theta 1
// lag g h t / 2: 0.18 mm at 0.15 s with its 0.25 ms step).
TEST(StepperRegistry, EveryStepperRunsAFreeFall) {
  for (const StepperEntry& s : Steppers()) {
    SCOPED_TRACE(s.name);
    const TrialResult r = RunTrial(FreeFall(s.name), {1, 0});
    ASSERT_EQ(r.status, Status::kTimeout) << r.detail;
    EXPECT_EQ(r.integrator, s.name);
    EXPECT_GT(r.counters.steps_taken, 0);
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.Summary();
    ASSERT_EQ(r.trace.size(), 4u);
    const std::string name = s.name;
    const double height_error = name == "SemiExplicitEuler2" ? 1e-4
                                : name == "MoreauJean"       ? 2e-4
                                                             : 1e-6;
    for (const TraceRow& row : r.trace) {
      EXPECT_NEAR(row.position.z(), 1.0 - 0.5 * kG * row.time * row.time, height_error)
          << row.time;
      EXPECT_NEAR(row.velocity.z(), -kG * row.time, 1e-6) << row.time;
    }
  }
}

}  // namespace
}  // namespace vahf::sim
