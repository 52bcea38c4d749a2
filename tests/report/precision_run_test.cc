// A small precision run end to end on the peg scene (three settings, three
// cycles, a few seconds): the run directory's tables, summary.json and
// measured.json have the documented structure, the reference compared with
// itself has no error, and one and two threads give the same results (and the
// same results digest): only the measured wall times differ.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "vahf/experiment/design.h"
#include "vahf/kinds/kind.h"
#include "vahf/report/output_directory.h"
#include "vahf/report/run_output.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::report {
namespace {

using ::testing::ElementsAre;

std::string Source(const std::string& relative) {
  const char* root = std::getenv("VAHF_SOURCE_DIR");
  return std::string(root ? root : VAHF_SOURCE_DIR) + "/" + relative;
}

std::filesystem::path TestDir() {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "vahf_precision_run_test";
  std::filesystem::create_directories(dir);
  return dir;
}

std::string Read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);) out.push_back(line);
  return out;
}

// The experiment: the peg at RungeKuttaMerson 1e-4 as the reference, against
// 1e-3, CPodes 1e-3 and a coarser visibility grid; 3 cycles each.
std::string WriteExperiment() {
  const nlohmann::json e = {
      {"format", "vahf-experiment/1"},
      {"name", "precision_run_test"},
      {"kind", "precision"},
      {"description", "end-to-end test"},
      {"seed", 1},
      {"trials", 3},
      {"scenes", {Source("experiments/scenes/peg_in_hole.json")}},
      {"reference",
       {{"simulation/integrator", "RungeKuttaMerson"}, {"simulation/accuracy", 1e-4}}},
      {"settings",
       {{{"simulation/integrator", "RungeKuttaMerson"}, {"simulation/accuracy", 1e-3}},
        {{"simulation/integrator", "CPodes"}, {"simulation/accuracy", 1e-3}},
        {{"visibility/grid", 32}}}},
      {"noise_trials", 12}};
  const std::filesystem::path path = TestDir() / "precision.json";
  std::ofstream(path) << e.dump(1);
  return path.string();
}

struct Output {
  std::string dir;
  std::string digest;
};

Output RunAndWrite(const scene::ExperimentFile& file, int threads) {
  experiment::RunSettings s;
  s.seed = file.seed;
  s.threads = threads;
  s.progress = false;
  const experiment::ExperimentRun run = kinds::RunDesign(file, s);
  const std::string dir = (TestDir() / ("threads" + std::to_string(threads))).string();
  OutputDirectory out(dir);
  RunInfo info;
  info.threads = threads;
  const RunOutput written = WriteRunOutput(run, kinds::Sections(run), out, info);
  EXPECT_TRUE(written.failed_plots.empty()) << written.failed_plots.front();
  return {dir, written.results_digest};
}

void WritesTheDocumentedFiles(const Output& one) {
  const std::string report = Read(std::filesystem::path(one.dir) / "report.md");
  EXPECT_NE(report.find("cycles per condition: peg_in_hole 3\n"), std::string::npos);
  EXPECT_EQ(report.find("The paper's claims"), std::string::npos);  // precision has none
  EXPECT_NE(report.find("**Recommended for peg_in_hole: "), std::string::npos);
  for (const char* f :
       {"manifest.json", "report.md", "summary.json", "measured.json",
        "precision_trials.csv", "precision_settings.csv", "precision_wall.csv",
        "plots/precision_peg_in_hole_difference.png",
        "plots/precision_peg_in_hole_ks.png", "plots/precision_peg_in_hole_outcomes.png"})
    EXPECT_GT(std::filesystem::file_size(std::filesystem::path(one.dir) / f), 0u) << f;
  const nlohmann::json manifest =
      nlohmann::json::parse(Read(std::filesystem::path(one.dir) / "manifest.json"));
  EXPECT_EQ(
      manifest["result_files"],
      (nlohmann::json{"precision_settings.csv", "precision_trials.csv", "summary.json"}));
  EXPECT_EQ(manifest["measured_files"],
            (nlohmann::json{"precision_wall.csv", "measured.json"}));
}

void TablesHaveARowPerTrialAndPerSetting(const Output& one) {
  const std::filesystem::path dir = one.dir;
  const std::vector<std::string> trials = Lines(Read(dir / "precision_trials.csv"));
  ASSERT_EQ(trials.size(), 1u + 4 * 3);  // header, 4 conditions x 3 cycles x 1 part
  EXPECT_EQ(trials[0],
            "scene,setting,cycle,position,part,status,completion_time_s,steps_taken,"
            "realizations");
  EXPECT_THAT(trials[1], ::testing::StartsWith(
                             "peg_in_hole,reference: RungeKuttaMerson 1e-4,0,0,peg,"));
  const std::vector<std::string> wall = Lines(Read(dir / "precision_wall.csv"));
  ASSERT_EQ(wall.size(), trials.size());
  EXPECT_EQ(wall[0], "scene,setting,cycle,position,part,status,wall_s");
  const std::vector<std::string> settings = Lines(Read(dir / "precision_settings.csv"));
  ASSERT_EQ(settings.size(), 1u + 4);
  EXPECT_THAT(settings[0],
              ::testing::StartsWith("scene,setting,reference,position,part,"));
}

void SummaryComparesEachSettingWithTheReference(const Output& one) {
  const nlohmann::json summary =
      nlohmann::json::parse(Read(std::filesystem::path(one.dir) / "summary.json"));
  const nlohmann::json& p = summary["sections"]["precision"];
  EXPECT_EQ(p["claims"], nlohmann::json::array());
  EXPECT_EQ(p["noise_trials"], 12);
  ASSERT_EQ(p["scenes"].size(), 1u);
  const nlohmann::json& scene = p["scenes"][0];
  EXPECT_EQ(scene["scene"], "peg_in_hole");
  EXPECT_EQ(scene["cycles"], 3);
  EXPECT_EQ(scene["parts"], nlohmann::json{"peg"});
  std::vector<std::string> labels;
  for (const auto& s : scene["settings"]) labels.push_back(s["setting"]);
  EXPECT_THAT(labels,
              ElementsAre("reference: RungeKuttaMerson 1e-4", "RungeKuttaMerson 1e-3",
                          "CPodes 1e-3", "visibility/grid 32"));
  // The reference against itself: no difference of any kind.
  const nlohmann::json& self = scene["settings"][0];
  EXPECT_EQ(self["reference"], true);
  EXPECT_EQ(self["overrides"]["simulation/accuracy"], 1e-4);
  const nlohmann::json& part = self["parts"][0];
  EXPECT_EQ(part["part"], "peg");
  EXPECT_EQ(part["cycles"], 3);
  EXPECT_EQ(part["paired"], part["completed"]);
  for (const char* key :
       {"mean_difference_s", "ci_lower_s", "ci_upper_s", "difference_bound_s",
        "mean_abs_difference_s", "ks_distance", "ks_shift_s", "outcome_share"})
    EXPECT_EQ(part[key], 0.0) << key;
  EXPECT_EQ(part["ks_p_value"], 1.0);
  EXPECT_EQ(part["p10_s"], part["reference_p10_s"]);
  EXPECT_EQ(part["meets_rule"], true);
  EXPECT_GT(part["noise_s"].get<double>(), 0.0);
  // Every setting carries the same statistics.
  for (const auto& s : scene["settings"])
    for (const char* key : {"mean_difference_s", "difference_bound_s", "ks_distance",
                            "ks_p_value", "outcome_share", "noise_s", "steps_median",
                            "realizations_median", "meets_rule", "failures"})
      EXPECT_TRUE(s["parts"][0].contains(key)) << s["setting"] << " " << key;
  // Noise is the reference's: the same for every setting.
  EXPECT_EQ(scene["settings"][1]["parts"][0]["noise_s"], part["noise_s"]);
}

void MeasuredJsonHoldsWallTimesAndTheRecommendation(const Output& one) {
  const nlohmann::json measured =
      nlohmann::json::parse(Read(std::filesystem::path(one.dir) / "measured.json"));
  const nlohmann::json& m = measured["sections"]["precision"];
  const nlohmann::json& rec = m["recommended"]["peg_in_hole"];
  for (const char* key :
       {"setting", "overrides", "wall_per_cycle_median_s", "errors", "why"})
    EXPECT_TRUE(rec.contains(key)) << key;
  EXPECT_TRUE(rec["errors"].contains("peg"));
  ASSERT_EQ(m["scenes"][0]["settings"].size(), 4u);
  for (const auto& s : m["scenes"][0]["settings"]) {
    EXPECT_GT(s["wall_per_cycle_median_s"].get<double>(), 0.0) << s["setting"];
    EXPECT_GT(s["parts"][0]["wall_median_s"].get<double>(), 0.0) << s["setting"];
  }
}

void OneAndTwoThreadsGiveTheSameResults(const Output& one, const Output& two) {
  EXPECT_EQ(one.digest, two.digest);
  for (const char* f : {"summary.json", "precision_trials.csv", "precision_settings.csv"})
    EXPECT_EQ(Read(std::filesystem::path(one.dir) / f),
              Read(std::filesystem::path(two.dir) / f))
        << f;
  // The measured wall table differs only in its wall times (the last column).
  const auto strip = [](const std::vector<std::string>& lines) {
    std::vector<std::string> out;
    for (const std::string& l : lines) out.push_back(l.substr(0, l.rfind(',')));
    return out;
  };
  EXPECT_EQ(strip(Lines(Read(std::filesystem::path(one.dir) / "precision_wall.csv"))),
            strip(Lines(Read(std::filesystem::path(two.dir) / "precision_wall.csv"))));
}

// One run on each thread count serves every check (ctest runs each TEST in a
// process of its own).
TEST(PrecisionRun, EndToEndOnThePegScene) {
  const scene::ExperimentFile file = kinds::LoadExperiment(WriteExperiment());
  const Output one = RunAndWrite(file, 1);
  const Output two = RunAndWrite(file, 2);
  {
    SCOPED_TRACE("files");
    WritesTheDocumentedFiles(one);
  }
  {
    SCOPED_TRACE("tables");
    TablesHaveARowPerTrialAndPerSetting(one);
  }
  {
    SCOPED_TRACE("summary");
    SummaryComparesEachSettingWithTheReference(one);
  }
  {
    SCOPED_TRACE("measured");
    MeasuredJsonHoldsWallTimesAndTheRecommendation(one);
  }
  {
    SCOPED_TRACE("threads");
    OneAndTwoThreadsGiveTheSameResults(one, two);
  }
}

}  // namespace
}  // namespace vahf::report
