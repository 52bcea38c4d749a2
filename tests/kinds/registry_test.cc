// Tests of the experiment-kind registry (kinds/kind.h): every kind is
// registered once with what parsing, checking and running need; a key only
// other kinds read names them; a paper run lists designs of cycles only, and
// every experiment it lists is validated before the first trial of any.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_files.h"
#include "vahf/core/error.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/paper_input.h"
#include "vahf/visibility/visibility.h"

namespace vahf::kinds {

namespace {

using ::nlohmann::json;
using ::testing::Contains;
using ::testing::HasSubstr;
using ::testing::Not;

std::string Source(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

std::filesystem::path TestDir() { return scene::testing::TestDir("vahf_registry_test"); }

// Writes `doc` into the running test's directory (made fresh by its first call).
std::string Write(const std::string& name, const json& doc) {
  static std::string test;
  const std::string running =
      ::testing::UnitTest::GetInstance()->current_test_info()->name();
  static std::filesystem::path dir;
  if (test != running) {
    test = running;
    dir = TestDir();
  }
  return scene::testing::WriteFile(dir / name, doc.dump(1));
}

json Experiment(const std::string& kind, const std::string& scene, int trials) {
  return {{"format", "vahf-experiment/1"},
          {"name", kind + "_test"},
          {"kind", kind},
          {"scene", scene},
          {"seed", 3},
          {"trials", trials}};
}

// The message of the InputError `f` throws ("" when it throws none).
template <typename F>
std::string ErrorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(KindRegistryTest, EveryKindIsRegisteredOnceWithWhatItsStagesNeed) {
  std::set<std::string> names;
  for (const Kind& k : Kinds()) {
    EXPECT_TRUE(names.insert(k.name).second) << k.name << " registered twice";
    EXPECT_FALSE(k.summary.empty()) << k.name;
    EXPECT_NE(k.parse, nullptr) << k.name;
    EXPECT_NE(k.check, nullptr) << k.name;
    EXPECT_FALSE(k.doc.empty()) << k.name;  // docs/kinds.md links it
    // Either a design of cycles with its analysis (the paper run analyses its
    // parts), or a run of its own; never both, never neither.
    EXPECT_NE(k.design == nullptr, k.run == nullptr) << k.name;
    if (k.design && k.name != "paper") {
      EXPECT_NE(k.analyse, nullptr) << k.name;
    }
    EXPECT_EQ(&FindKind(k.name), &k);
  }
}

// The kinds of the shipped experiments (experiments/*.json), each once.
std::set<std::string> ShippedKinds() {
  std::set<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(Source("experiments"))) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    const json doc = json::parse(in);
    if (doc.value("format", "") == "vahf-experiment/1") out.insert(doc.value("kind", ""));
  }
  return out;
}

// The kinds docs/kinds.md lists, in its order: the first cell of each row.
std::vector<std::string> DocumentedKinds() {
  std::ifstream in(Source("docs/kinds.md"));
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("| `", 0) == 0) out.push_back(line.substr(3, line.find('`', 3) - 3));
  return out;
}

// Every registered kind has a shipped example and a line in docs/kinds.md, in
// the registry's order; no shipped experiment names a kind that is not there.
TEST(KindRegistryTest, TheHandbooksReadTheOneKindThatTimesThePartsForOperators) {
  std::vector<std::string> timing;
  for (const Kind& k : Kinds())
    if (k.times_the_parts) timing.push_back(k.name);
  EXPECT_EQ(timing, std::vector<std::string>{"assembly_time"});
  // Only a design of cycles has cycles to time.
  EXPECT_NE(FindKind("assembly_time").design, nullptr);
}

TEST(KindRegistryTest, TheShippedExperimentsAndTheDocsNameTheRegisteredKinds) {
  const std::vector<std::string> names = KindNames();
  EXPECT_EQ(ShippedKinds(), std::set<std::string>(names.begin(), names.end()));
  EXPECT_EQ(DocumentedKinds(), names);
}

TEST(KindRegistryTest, TheKindIndexIsCurrent) {
  std::ifstream in(Source("docs/kinds.md"));
  ASSERT_TRUE(in) << "docs/kinds.md is missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), KindIndexMarkdown())
      << "docs/kinds.md is out of date: regenerate it with `vahf kinds > docs/kinds.md`";
}

TEST(KindRegistryTest, EveryShippedExperimentLoadsWithARegisteredKind) {
  for (const auto& entry : std::filesystem::directory_iterator(Source("experiments"))) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    if (json::parse(in).value("format", "") != "vahf-experiment/1") continue;
    const scene::ExperimentFile e = LoadExperiment(entry.path().string());
    EXPECT_EQ(FindKind(e.kind).name, e.kind) << entry.path();
  }
}

TEST(KindRegistryTest, AnUnregisteredKindNamesTheRegisteredOnes) {
  const std::string path =
      Write("planned.json",
            Experiment("no_such_kind", Source("experiments/scenes/peg_in_hole.json"), 1));
  // The example is a name no kind may take.
  ASSERT_THAT(KindNames(), Not(Contains("no_such_kind")));
  const std::string message = ErrorOf([&] { LoadExperiment(path); });
  EXPECT_THAT(message, HasSubstr(path));
  EXPECT_THAT(message, HasSubstr("/kind"));
  EXPECT_THAT(message, HasSubstr("no_such_kind"));
  for (const Kind& k : Kinds()) EXPECT_THAT(message, HasSubstr(k.name));
}

TEST(KindRegistryTest, AKeyOnlyOtherKindsReadNamesEveryKindThatReadsIt) {
  json doc = Experiment("table1", Source("experiments/scenes/peg_in_hole.json"), 1);
  doc["fatigue"] = {{"segments", 2}};
  const std::string message = ErrorOf([&] { LoadExperiment(Write("t.json", doc)); });
  EXPECT_THAT(message, HasSubstr("/fatigue"));
  EXPECT_THAT(
      message,
      HasSubstr("only an experiment of kind \"fatigue\", \"calibrate\" or \"compare\" "
                "reads \"fatigue\""));
}

TEST(KindRegistryTest, APaperRunListsDesignsOfCyclesOnly) {
  const std::string calibrate = Source("experiments/calibrate_paper.json");
  const json paper = {{"format", "vahf-experiment/1"},
                      {"name", "paper_test"},
                      {"kind", "paper"},
                      {"experiments", {Source("experiments/table1.json"), calibrate}}};
  const std::string path = Write("paper.json", paper);
  const std::string message = ErrorOf([&] { LoadExperiment(path); });
  EXPECT_THAT(message, HasSubstr(path));
  EXPECT_THAT(message, HasSubstr("/experiments/1"));
  EXPECT_THAT(message, HasSubstr("is a calibrate experiment"));
}

// The second experiment's scene is changed after loading (as a calibration's
// trial values are) so that only building its trial models rejects it: a
// contact shell of more than contact::kMaxShellPoints points. The first asks
// for a million cycles: a run that validated lazily would simulate for hours
// before it met the fault, so this test fails by its time-out then; a run
// that validates first throws at once, having simulated nothing.
TEST(KindRegistryTest, APaperRunValidatesEveryExperimentBeforeTheFirstTrial) {
  const std::string bad_scene = Source("experiments/scenes/peg_in_hole.json");
  const std::string first = Write(
      "first.json",
      Experiment("table1", Source("experiments/scenes/peg_in_hole.json"), 1'000'000));
  const std::string second = Write("second.json", Experiment("table1", bad_scene, 1));
  const json paper = {{"format", "vahf-experiment/1"},
                      {"name", "paper_test"},
                      {"kind", "paper"},
                      {"experiments", {first, second}}};
  scene::ExperimentFile file = LoadExperiment(Write("paper.json", paper));
  ASSERT_EQ(file.Input<PaperInput>().experiments.size(), 2u);
  file.UpdInput<PaperInput>().experiments[1].scene.params.contact.shell_spacing = 1e-5;
  const std::string checked = ErrorOf([&] { CheckExperiment(file); });
  EXPECT_THAT(checked, HasSubstr(bad_scene));
  EXPECT_THAT(checked, HasSubstr("/parameters/contact"));
  EXPECT_THAT(checked, HasSubstr("contact shell"));

  const std::filesystem::path run = std::filesystem::path(first).parent_path() / "run";
  report::OutputDirectory out(run.string());
  RunContext context;
  context.settings.progress = false;
  context.directory = &out;
  const std::string ran = ErrorOf([&] { RunExperiment(file, context); });
  EXPECT_EQ(ran, checked);
  EXPECT_FALSE(std::filesystem::exists(run / "report.md"));
}

}  // namespace
}  // namespace vahf::kinds
