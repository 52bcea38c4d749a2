// The calibration report: a parameter the targets do not determine is named
// with its reason and gets no interval; one the cost bounds on one side only
// says so; the rank, correlations, Monte Carlo spread, the scan's table and
// plot are there (docs/calibration.md, Identifiability).
#include "vahf/report/calibration_section.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "vahf/data/lab_dataset.h"
#include "vahf/kinds/kind.h"

namespace vahf::report {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string Path(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

const Table& TableNamed(const Section& s, const std::string& name) {
  for (const auto& [file, table] : s.tables)
    if (file == name) return table;
  ADD_FAILURE() << "no table " << name;
  return s.tables.at(0).second;
}

// A stage of experiments/calibrate_reach_synthetic.json, its result made by
// hand: d1 identified but not bounded below, d2 not identified, d3 and
// kappa identified.
calibrate::CalibrationResult Result() {
  calibrate::CalibrationResult r;
  r.solver = "levenberg_marquardt";
  r.converged = true;
  const char* names[] = {"reach/d1_arm_fraction", "reach/d2_height_fraction",
                         "reach/d3_height_fraction", "guidance/kappa"};
  const double estimate[] = {0.76, 0.48, 0.68, 251.0};
  for (int i = 0; i < 4; ++i) {
    calibrate::FittedParameter p;
    p.name = names[i];
    p.estimate = estimate[i];
    p.edge_lower = estimate[i] * 0.9;
    p.edge_upper = estimate[i] * 1.1;
    p.rise_lower = i == 0 ? 0.21 : 5.0;
    p.rise_upper = 5.0;
    p.scan = {{p.edge_lower, p.rise_lower}, {estimate[i], 0.0}, {p.edge_upper, 5.0}};
    p.mc_sd = i == 1 ? kNaN : 0.1 * estimate[i];
    p.standard_error = i == 1 ? kNaN : 0.2 * estimate[i];
    p.ci = {p.estimate - 1.96 * p.standard_error, p.estimate + 1.96 * p.standard_error};
    if (i == 1) {
      p.identified = false;
      p.not_identified_why = "the cost rises by less than 1.92 to either end";
    }
    r.parameters.push_back(p);
  }
  r.covariance = Eigen::MatrixXd::Identity(4, 4);
  r.covariance(1, 1) = kNaN;
  r.covariance_ok = true;
  r.correlation = calibrate::Correlation(r.covariance);
  r.rank.rank = 3;
  r.rank.singular_values = Eigen::Vector4d(115, 16.4, 0.35, 0);
  r.rank.condition = 115 / 0.35;
  r.noise_replicates = 4;
  return r;
}

TEST(CalibrationSection, NamesWhatTheTargetsDoNotDetermineAndDrawsTheScan) {
  const scene::ExperimentFile file =
      kinds::LoadExperiment(Path("experiments/calibrate_reach_synthetic.json"));
  const data::LabDataset lab =
      data::LoadLabDataset(Path("data/synthetic_block/dataset.json"));
  const Section s = CalibrationSection(file, lab, {Result()});
  for (const char* text : {"**not identified**",
                           "`reach/d2_height_fraction` is **not identified**: the cost "
                           "rises by less than 1.92 to either end",
                           "not bounded below it", "has rank 3 of 4", "| correlation |",
                           "of which Monte Carlo", "over 4 other sets of virtual people"})
    EXPECT_NE(s.markdown.find(text), std::string::npos) << text << "\n" << s.markdown;
  // No parameter is open above: its cost rises past 1.92 to its upper end.
  EXPECT_EQ(s.markdown.find("not bounded above"), std::string::npos);
  const std::string params = TableNamed(s, "calibrate_parameters.csv").ToCsv();
  EXPECT_NE(params.find("identified"), std::string::npos);
  EXPECT_NE(params.find("monte_carlo_sd"), std::string::npos);
  EXPECT_EQ(TableNamed(s, "calibrate_scan.csv").rows(), 12u);  // 3 points, 4 parameters
  bool scan_plot = false;
  for (const Plot& p : s.plots)
    scan_plot = scan_plot || p.file == "plots/calibrate_scan.png";
  EXPECT_TRUE(scan_plot);
  ASSERT_EQ(s.summary["parameters"].size(), 4u);
  EXPECT_FALSE(s.summary["parameters"][1]["identified"].get<bool>());
  EXPECT_TRUE(s.summary["parameters"][3]["identified"].get<bool>());
}

// With "intervals": "profile", each identified parameter's profile points
// are a table and a plot of their own, an end not reached says so, and a
// re-fit that found a lower cost than the estimate's is named.
TEST(CalibrationSection, AProfileStageDrawsTheProfileAndNamesAFitStoppedShort) {
  scene::ExperimentFile file =
      kinds::LoadExperiment(Path("experiments/calibrate_reach_synthetic.json"));
  calibrate::CalibrationDesign& design = file.UpdInput<calibrate::CalibrationDesign>();
  design.intervals = "profile";
  const data::LabDataset lab =
      data::LoadLabDataset(Path("data/synthetic_block/dataset.json"));
  calibrate::CalibrationResult r = Result();
  for (calibrate::FittedParameter& p : r.parameters) {
    if (!p.identified) continue;
    p.has_profile = true;
    p.profile = {p.estimate * 0.95, p.estimate * 1.08};
    p.profile_points = {
        {p.estimate * 0.95, 1.92}, {p.estimate, 0}, {p.estimate * 1.08, 1.9}};
  }
  r.parameters[3].profile_reached = false;
  r.profile_least_rise = -0.8;
  const Section s = CalibrationSection(file, lab, {r});
  EXPECT_EQ(TableNamed(s, "calibrate_profile.csv").rows(), 9u);  // 3 points, 3 identified
  bool profile_plot = false;
  for (const Plot& p : s.plots)
    profile_plot = profile_plot || p.file == "plots/calibrate_profile.png";
  EXPECT_TRUE(profile_plot);
  for (const char* text : {"the others re-fitted", "(an end not reached: wider)",
                           "A re-fit of the profile found a cost 0.8 below"})
    EXPECT_NE(s.markdown.find(text), std::string::npos) << text << "\n" << s.markdown;
  // summary.json carries the least rise too; a Wald stage's has no such key.
  EXPECT_DOUBLE_EQ(s.summary["stages"][0]["profile_least_rise"].get<double>(), -0.8);
  design.intervals = "wald";
  for (calibrate::FittedParameter& p : r.parameters) p.has_profile = false;
  EXPECT_FALSE(CalibrationSection(file, lab, {r})
                   .summary["stages"][0]
                   .contains("profile_least_rise"));
}

}  // namespace
}  // namespace vahf::report
