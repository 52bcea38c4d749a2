// Tests of the stability kind's file and verdicts: a valid file loads with its
// cases, patches, overrides, integrators and expectations (the patch and the
// overrides reach the scene each integrator runs); every malformed variant is
// one InputError naming the experiment file, the exact JSON pointer of the
// case's fault, the value and the rule (a patch pointer the scene does not
// hold, a patched value breaking a scene rule, an unknown outcome class, a
// position past the sequence, ...); and StabilityFailures fails a trial on an
// unexpected status, a number that is not finite, or too many steps.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "support/test_files.h"
#include "vahf/core/error.h"
#include "vahf/experiment/stability_design.h"
#include "vahf/experiment/stability_input.h"
#include "vahf/kinds/kind.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::scene {

using experiment::StabilityCase;
using experiment::StabilityDesign;
namespace {

using ::nlohmann::json;
using ::testing::ElementsAre;
using testing::WriteFile;

std::string Source(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

std::filesystem::path TestDir() { return testing::TestDir("vahf_stability_test"); }

json Case(const std::string& name) {
  return {{"name", name},
          {"scene", Source("experiments/scenes/peg_in_hole.json")},
          {"expect", {"completed"}}};
}

json Stability() {
  json e = {{"format", "vahf-experiment/1"},
            {"name", "stability_test"},
            {"kind", "stability"},
            {"integrators", {"CVODE", "RungeKuttaMerson"}},
            {"cases", json::array()}};
  json tight = Case("tight");
  tight["patch"] = {{"/parts/1/geometry/profile/2", {0.010049, 0.0005}},
                    {"/parts/1/geometry/profile/3", {0.010049, 0.05}},
                    {"/parts/1/friction", 0.4}};
  tight["parameters"] = {{"simulation/time_limit", 1.5}, {"contact/stiffness", 1e12}};
  tight["expect"] = {"completed", "jammed"};
  tight["seeds"] = 2;
  json fixed = Case("fixed");
  fixed["integrators"] = {"FixedStep"};
  fixed["position"] = 0;
  fixed["expect"] = {"numerical_failure", "step_budget"};
  e["cases"] = {tight, fixed};
  return e;
}

ExperimentFile Load(const json& doc) {
  const std::string path = WriteFile(TestDir() / "stability.json", doc.dump(1));
  ExperimentFile e = kinds::LoadExperiment(path);
  kinds::CheckExperiment(e);
  return e;
}

// LoadExperiment then CheckExperiment (as `vahf check` and `vahf run` do)
// throw one InputError naming the experiment file at `where`.
void ExpectError(const json& doc, const std::string& where, const std::string& rule,
                 const std::string& value = "") {
  const std::string path = WriteFile(TestDir() / "stability.json", doc.dump(1));
  testing::ExpectInputError([&] { kinds::CheckExperiment(kinds::LoadExperiment(path)); },
                            path, where, rule, value);
}

TEST(StabilityFile, LoadsCasesWithTheirPatchesOverridesAndIntegrators) {
  const ExperimentFile e = Load(Stability());
  EXPECT_EQ(e.kind, "stability");
  EXPECT_THAT(e.Input<StabilityDesign>().integrators,
              ElementsAre("CVODE", "RungeKuttaMerson"));
  ASSERT_EQ(e.Input<StabilityDesign>().cases.size(), 2u);
  const StabilityCase& tight = e.Input<StabilityDesign>().cases[0];
  EXPECT_EQ(tight.name, "tight");
  EXPECT_EQ(tight.pointer, "/cases/0");
  EXPECT_EQ(tight.seeds, 2);
  EXPECT_THAT(tight.expect, ElementsAre("completed", "jammed"));
  EXPECT_THAT(tight.expect_pointers,
              ElementsAre("/cases/0/expect/0", "/cases/0/expect/1"));
  EXPECT_THAT(tight.integrators, ElementsAre("CVODE", "RungeKuttaMerson"));
  ASSERT_EQ(tight.scenes.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const Scene& s = tight.scenes[i];
    EXPECT_EQ(s.params.simulation.integrator, tight.integrators[i]);
    EXPECT_EQ(s.params.simulation.time_limit, 1.5);
    EXPECT_EQ(s.params.contact.stiffness, 1e12);
    EXPECT_EQ(s.params.simulation.accuracy, 3e-5);  // the scene's own, kept
    EXPECT_EQ(s.parts[1].friction, 0.4);
    EXPECT_EQ(s.parts[0].friction, 0.15);  // unpatched
  }
  const StabilityCase& fixed = e.Input<StabilityDesign>().cases[1];
  EXPECT_THAT(fixed.integrators, ElementsAre("FixedStep"));
  EXPECT_EQ(fixed.scenes[0].params.simulation.integrator, "FixedStep");
  EXPECT_EQ(fixed.seeds, 1);
  EXPECT_EQ(e.scene_path, Source("experiments/scenes/peg_in_hole.json"));
}

TEST(StabilityFile, APatchPointerMustNameAValueTheSceneHolds) {
  json e = Stability();
  e["cases"][0]["patch"] = {{"/parts/1/mass", 0.001}};  // the peg gives a density
  ExpectError(e, "/cases/0/patch/~1parts~11~1mass", "the scene has no 'mass' at /parts/1",
              "0.001");
  e["cases"][0]["patch"] = {{"/parts/7/friction", 0.2}};
  ExpectError(e, "/cases/0/patch/~1parts~17~1friction",
              "holds 2 elements; '7' names none");
  e["cases"][0]["patch"] = {{"parts/1/friction", 0.2}};
  ExpectError(e, "/cases/0/patch/parts~11~1friction", "starts with '/'");
  e["cases"][0]["patch"] = {{"/parts/99999999999999999999999/friction", 0.2}};
  ExpectError(e, "/cases/0/patch/~1parts~199999999999999999999999~1friction",
              "holds 2 elements; '99999999999999999999999' names none");
  e["cases"][0]["patch"] = {{"/parts/01/friction", 0.2}};
  ExpectError(e, "/cases/0/patch/~1parts~101~1friction", "'01' names none");
  e["cases"][0]["patch"] = {{"/parts/1/fr~2", 0.2}};
  ExpectError(e, "/cases/0/patch/~1parts~11~1fr~02", "writes '~' as ~0");
  e["cases"][0]["patch"] = {{"", 0.2}};
  ExpectError(e, "/cases/0/patch/", "starts with '/'");
  e["cases"][0]["patch"] = {{"/name/x", 0.2}};
  ExpectError(e, "/cases/0/patch/~1name~1x", "/name is a string");
  e["cases"][0]["patch"] = {{"/parts/1", json::object()}, {"/parts/1/friction", 0.2}};
  ExpectError(e, "/cases/0/patch/~1parts~11~1friction", "lies inside /parts/1");
  e["cases"][0]["patch"] = json::array();
  ExpectError(e, "/cases/0/patch", "an object of JSON pointer");
}

TEST(StabilityFile, APatchedSceneBreakingARuleNamesThePatchEntry) {
  json e = Stability();
  e["cases"][1]["patch"] = {{"/parts/1/density", -5}};
  ExpectError(e, "/cases/1/patch/~1parts~11~1density", "must lie in [1, 1e7]", "-5");
  // Inside a patched value: the pointer goes on into it.
  e["cases"][1]["patch"] = {
      {"/parts/1/geometry/profile", {{0, 0}, {-0.01, 0}, {0, 0.05}, {0, 0}}}};
  ExpectError(e, "/cases/1/patch/~1parts~11~1geometry~1profile/1", "negative", "-0.01");
  // A rule the patch breaks elsewhere in the scene names the case.
  e["cases"][1]["patch"] = {{"/parts/1/role", "base"}};
  ExpectError(e, "/cases/1", "with the case's patch");
}

TEST(StabilityFile, OverridesIntegratorsSeedsAndPositionFollowTheirRules) {
  json e = Stability();
  e["cases"][1]["parameters"] = {{"simulation/accuracy", 0.0}};
  ExpectError(e, "/cases/1/parameters/simulation~1accuracy", "must lie in [1e-12, 0.5]");
  e["cases"][1]["parameters"] = {{"simulation/integrator", "CVODE"}};
  ExpectError(e, "/cases/1/parameters/simulation~1integrator", "in \"integrators\"");
  e["cases"][1]["parameters"] = {{"simulation/acuracy", 1e-4}};
  ExpectError(e, "/cases/1/parameters/simulation~1acuracy", "did you mean");
  e = Stability();
  e["integrators"] = {"CVODE", "Euler"};
  ExpectError(e, "/integrators/1", "must be one of", "Euler");
  e["integrators"] = {"CVODE", "CVODE"};
  ExpectError(e, "/integrators/1", "listed once");
  e = Stability();
  e["cases"][0]["seeds"] = 0;
  ExpectError(e, "/cases/0/seeds", "must lie in [1, 1000]");
  e = Stability();
  e["cases"][0]["position"] = 1;
  ExpectError(e, "/cases/0/position", "has 1 part(s)");
  e = Stability();
  e["cases"][1]["name"] = "tight";
  ExpectError(e, "/cases/1/name", "unique");
  e = Stability();
  e["cases"][0]["scene"] = "no_such_scene.json";
  ExpectError(e, "/cases/0/scene", "no scene file");
  e = Stability();
  e["cases"] = json::array();
  ExpectError(e, "/cases", "at least 1 element");
  e = Stability();
  e["scene"] = Source("experiments/scenes/peg_in_hole.json");
  ExpectError(e, "/scene", "in each of its \"cases\"");
}

TEST(StabilityFile, AnExpectedClassIsATrialStatus) {
  json e = Stability();
  e["cases"][1]["expect"] = {"numerical_failure", "crashed"};
  ExpectError(e, "/cases/1/expect/1",
              "a trial status: completed, timeout, exhausted, "
              "unreachable, jammed, numerical_failure, step_budget",
              "crashed");
  e["cases"][1]["expect"] = {"jammed", "jammed"};
  ExpectError(e, "/cases/1/expect/1", "listed once");
  e["cases"][1]["expect"] = json::array();
  ExpectError(e, "/cases/1/expect", "at least 1 element");
}

TEST(StabilityFile, TheOutcomeClassesAreTheStatusNames) {
  std::vector<std::string> names;
  for (int s = 0; s <= static_cast<int>(sim::Status::kStepBudget); ++s)
    names.push_back(sim::StatusName(static_cast<sim::Status>(s)));
  EXPECT_EQ(experiment::OutcomeClasses(), names);
  EXPECT_TRUE(experiment::IsOutcomeClass("step_budget"));
  EXPECT_FALSE(experiment::IsOutcomeClass("?"));
}

// ---------------------------------------------------------------------------
// The verdict on one trial.

sim::TrialResult Completed() {
  sim::TrialResult r;
  r.status = sim::Status::kCompleted;
  r.end_time = 0.1;
  r.counters.steps_taken = 800;
  r.counters.steps_attempted = 850;
  return r;
}

StabilityCase Expecting(std::vector<std::string> classes) {
  StabilityCase c;
  c.name = "c";
  c.expect = std::move(classes);
  return c;
}

TEST(StabilityVerdict, PassesAnExpectedFiniteTrialWithinItsSteps) {
  EXPECT_THAT(
      experiment::StabilityFailures(Expecting({"jammed", "completed"}), Completed(), 800),
      ::testing::IsEmpty());
}

TEST(StabilityVerdict, FailsAnUnexpectedStatus) {
  EXPECT_THAT(
      experiment::StabilityFailures(Expecting({"jammed", "timeout"}), Completed(), 1000),
      ElementsAre("ended completed, expected jammed or timeout"));
}

TEST(StabilityVerdict, FailsANumberThatIsNotFinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  sim::TrialResult r = Completed();
  r.final_row.velocity.y() = nan;
  EXPECT_THAT(experiment::StabilityFailures(Expecting({"completed"}), r, 1000),
              ElementsAre("not finite: final row"));
  r = Completed();
  r.max_penetration = std::numeric_limits<double>::infinity();
  r.work = nan;
  EXPECT_THAT(experiment::StabilityFailures(Expecting({"completed"}), r, 1000),
              ElementsAre("not finite: work, deepest contact"));
  r = Completed();
  r.final_row.factors.eta = nan;
  EXPECT_THAT(experiment::StabilityFailures(Expecting({"completed"}), r, 1000),
              ElementsAre("not finite: final row"));
}

TEST(StabilityVerdict, FailsATrialBeyondItsStepBudget) {
  EXPECT_THAT(experiment::StabilityFailures(Expecting({"completed"}), Completed(), 799),
              ElementsAre("800 accepted steps, over simulation/max_steps 799"));
}

}  // namespace
}  // namespace vahf::scene
