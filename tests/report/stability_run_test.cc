// A small stability run end to end on the free block (three cases, a second
// or two): a suite whose cases all end as they expect exits 0 and writes the
// documented files (the trials table, the measured cost table, summary.json,
// measured.json, report.md with a row per case and integrator); one and two
// threads give the same results digest; and a case expecting a class it
// cannot reach makes the run exit 1, naming the case on one line, with every
// output still written and the case marked FAIL.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/test_files.h"
#include "vahf/kinds/kind.h"
#include "vahf/report/output_directory.h"
#include "vahf/report/stability_section.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::report {
namespace {

using ::testing::HasSubstr;

std::string Source(const std::string& relative) {
  const char* root = std::getenv("VAHF_SOURCE_DIR");
  return std::string(root ? root : VAHF_SOURCE_DIR) + "/" + relative;
}

// Kept across a test's runs (scene::testing::TestDir empties its folder).
std::filesystem::path TestDir() {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "vahf_stability_run_test";
  std::filesystem::create_directories(dir);
  return dir;
}

using scene::testing::Lines;
using scene::testing::ReadFile;

nlohmann::json Case(const std::string& name, const std::vector<std::string>& expect) {
  return {{"name", name},
          {"scene", Source("experiments/scenes/free_move.json")},
          {"parameters", {{"simulation/time_limit", 3.0}}},
          {"expect", expect}};
}

// The block carried across free space (completes), an operator standing 2 m
// away (unreachable) and one who tires at once (exhausted).
nlohmann::json Suite() {
  nlohmann::json moves = Case("moves", {"completed"});
  moves["seeds"] = 2;
  nlohmann::json far = Case("out_of_reach", {"unreachable"});
  far["patch"] = {{"/operator/position", {0.0, -2.0}}};
  far["integrators"] = {"CVODE"};
  nlohmann::json tired = Case("tired", {"exhausted"});
  tired["parameters"]["fatigue/a_max"] = 1e-3;
  tired["integrators"] = {"RungeKuttaMerson"};
  return {{"format", "vahf-experiment/1"},
          {"name", "stability_run_test"},
          {"kind", "stability"},
          {"description", "end-to-end test"},
          {"seed", 1},
          {"integrators", {"RungeKuttaMerson", "CVODE"}},
          {"cases", {moves, far, tired}}};
}

std::string WriteExperiment(const nlohmann::json& doc, const std::string& name) {
  const std::filesystem::path path = TestDir() / (name + ".json");
  std::ofstream(path) << doc.dump(1);
  return path.string();
}

struct Output {
  std::string dir;
  int status = -1;
  std::string err;
};

Output RunSuite(const nlohmann::json& doc, const std::string& name, int threads) {
  const scene::ExperimentFile file = kinds::LoadExperiment(WriteExperiment(doc, name));
  Output o;
  o.dir = (TestDir() / (name + "_threads" + std::to_string(threads))).string();
  OutputDirectory out(o.dir);
  kinds::RunContext context;
  context.settings.seed = file.seed;
  context.settings.threads = threads;
  context.settings.progress = false;
  context.directory = &out;
  ::testing::internal::CaptureStderr();
  o.status = kinds::RunExperiment(file, context);
  o.err = ::testing::internal::GetCapturedStderr();
  return o;
}

TEST(StabilityRun, ASuiteEndingAsItExpectsPassesAndWritesItsReport) {
  const Output one = RunSuite(Suite(), "pass", 1);
  EXPECT_EQ(one.status, 0) << one.err;
  EXPECT_EQ(one.err.find("vahf: error"), std::string::npos) << one.err;
  const std::filesystem::path dir = one.dir;
  for (const char* f : {"manifest.json", "report.md", "summary.json", "measured.json",
                        "stability_trials.csv", "stability_cost.csv"})
    EXPECT_GT(std::filesystem::file_size(dir / f), 0u) << f;
  const nlohmann::json manifest = nlohmann::json::parse(ReadFile(dir / "manifest.json"));
  EXPECT_EQ(manifest["result_files"],
            (nlohmann::json{"stability_trials.csv", "summary.json"}));
  EXPECT_EQ(manifest["measured_files"],
            (nlohmann::json{"stability_cost.csv", "measured.json"}));
  // A row per trial: moves 2 integrators x 2 seeds, out_of_reach 1, tired 1.
  const std::vector<std::string> rows = Lines(ReadFile(dir / "stability_trials.csv"));
  ASSERT_EQ(rows.size(), 1u + 4 + 1 + 1);
  EXPECT_THAT(rows[0],
              ::testing::StartsWith("case,integrator,seed_index,status,expected,pass,"));
  EXPECT_THAT(rows[1],
              ::testing::StartsWith("moves,RungeKuttaMerson,0,completed,completed,yes,"));
  EXPECT_THAT(rows[4], ::testing::StartsWith("moves,CVODE,1,completed,completed,yes,"));
  EXPECT_THAT(rows[5],
              ::testing::StartsWith("out_of_reach,CVODE,0,unreachable,unreachable,yes,"));
  EXPECT_THAT(rows[6],
              ::testing::StartsWith("tired,RungeKuttaMerson,0,exhausted,exhausted,yes,"));
  EXPECT_EQ(Lines(ReadFile(dir / "stability_cost.csv")).size(), rows.size());
  const nlohmann::json summary = nlohmann::json::parse(ReadFile(dir / "summary.json"));
  const nlohmann::json& s = summary["sections"]["stability"];
  EXPECT_EQ(s["passed"], true);
  EXPECT_EQ(s["failed_cases"], nlohmann::json::array());
  ASSERT_EQ(s["cases"].size(), 3u);
  EXPECT_EQ(s["cases"][0]["integrators"].size(), 2u);
  EXPECT_EQ(s["cases"][0]["integrators"][1]["trials"][1]["status"], "completed");
  const nlohmann::json measured = nlohmann::json::parse(ReadFile(dir / "measured.json"));
  ASSERT_EQ(measured["sections"]["stability"]["trials"].size(), 6u);
  for (const auto& t : measured["sections"]["stability"]["trials"])
    EXPECT_GT(t["cpu_s"].get<double>(), 0.0) << t;
  const std::string report = ReadFile(dir / "report.md");
  EXPECT_THAT(report, HasSubstr("Every case passes."));
  EXPECT_THAT(report, HasSubstr("| moves | CVODE | completed 2 | completed | pass |"));
  EXPECT_THAT(report,
              HasSubstr("| tired | RungeKuttaMerson | exhausted | exhausted | pass |"));

  // Two threads: the same results, to the bit.
  const Output two = RunSuite(Suite(), "pass", 2);
  EXPECT_EQ(two.status, 0);
  EXPECT_EQ(nlohmann::json::parse(ReadFile(std::filesystem::path(two.dir) /
                                           "manifest.json"))["results_digest"],
            manifest["results_digest"]);
  EXPECT_EQ(ReadFile(std::filesystem::path(two.dir) / "stability_trials.csv"),
            ReadFile(dir / "stability_trials.csv"));
}

TEST(StabilityRun, ACaseEndingOtherwiseFailsTheRunWithItsOutputsWritten) {
  nlohmann::json doc = Suite();
  doc["cases"][1]["expect"] = {"jammed"};  // the far operator cannot jam in free space
  const Output o = RunSuite(doc, "fail", 2);
  EXPECT_EQ(o.status, 1);
  EXPECT_THAT(o.err, HasSubstr("vahf: error: stability: 1 case(s) failed (results kept): "
                               "out_of_reach\n"));
  const std::filesystem::path dir = o.dir;
  const nlohmann::json summary = nlohmann::json::parse(ReadFile(dir / "summary.json"));
  const nlohmann::json& s = summary["sections"]["stability"];
  EXPECT_EQ(s["passed"], false);
  EXPECT_EQ(s["failed_cases"], nlohmann::json{"out_of_reach"});
  EXPECT_EQ(s["cases"][0]["passed"], true);
  EXPECT_EQ(s["cases"][1]["passed"], false);
  EXPECT_EQ(s["cases"][1]["integrators"][0]["trials"][0]["failures"],
            nlohmann::json{"ended unreachable, expected jammed"});
  const std::string report = ReadFile(dir / "report.md");
  EXPECT_THAT(report, HasSubstr("1 case(s) fail: out_of_reach."));
  EXPECT_THAT(report,
              HasSubstr("| out_of_reach | CVODE | unreachable | jammed | **FAIL**: "
                        "ended unreachable, expected jammed |"));
  EXPECT_THAT(ReadFile(dir / "stability_trials.csv"),
              HasSubstr("out_of_reach,CVODE,0,unreachable,jammed,no,"));
}

TEST(StabilityRun, CompactWarningsCountsEachKind) {
  Warnings w;
  EXPECT_EQ(CompactWarnings(w), "-");
  w.Note(WarningKind::kIntegratorRetry, 0.1, "x", 9);
  w.Note(WarningKind::kPenetrationBound, 0.2, "y", 709);
  EXPECT_EQ(CompactWarnings(w), "pen 709, retry 9");
}

}  // namespace
}  // namespace vahf::report
