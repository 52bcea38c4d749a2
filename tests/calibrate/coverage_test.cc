// Coverage of a joint calibration's 95 % intervals (docs/calibration.md,
// "Synthetic data"): the model at values only this test states plays the lab
// (synthetic_lab.h: operators' times and an hour of work's segments), and ONE
// stage fits the reach curve's fractions D1-D3, kappa and A_max back to each
// operator's mean time and each segment's success rate. Over datasets of
// other lab seeds (the truth fixed), each fitted with its own virtual seed,
// the share of profile intervals ("intervals": "profile") that hold the
// truth is counted per parameter; a D the targets do not determine
// (identifiability.h) has no interval and is counted apart. kappa and A_max
// must be identified every time. The Wald intervals and the Mahalanobis
// distances of the Wald covariance are printed beside them.
//
// The CI size is 3 datasets, checked by an exact binomial bound on each
// coverage. VAHF_COVERAGE_DATASETS=N runs N datasets instead (the full size
// is 50: every coverage then 90 % or more, and each profile interval's
// implied standard error, half its width / 1.96, on average within a factor
// 2 of the estimates' sd); VAHF_COVERAGE_FIRST=K starts at dataset K;
// VAHF_COVERAGE_CSV=PATH also writes one row per dataset and parameter
// there; VAHF_COVERAGE_VERBOSE prints every evaluation and each profile.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "support/quiet_runner.h"
#include "vahf/calibrate/calibration.h"
#include "vahf/calibrate/synthetic_lab.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::calibrate {
namespace {

std::string Path(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

// The truth: none of them the scene's or the paper's value. D1 = 0.62 arm
// lies where the block's path crosses the reach curve's first slope for
// every operator (the times fall by 3-4 % per 0.04 of d1, nearly linearly
// from 0.55 to 0.70; at 0.8 the curve has flattened and d1 barely moves
// them), D3 beyond every distance of the path (not identified by design).
// A_max is set so that the operator tires within the hour: at these values
// the steel block's work rate is about 9.2 J per second of assembly
// (measured, a fatigue run's pilot), and a cycle fails once Psi_c <= 0.05,
// so segments 1 and 2 succeed, segment 3 about 70 % of the time, segment 4
// never. The starts lie a little off the truth (about one standard error).
struct Truth {
  const char* name;
  double value, start, lower, upper;
};
constexpr std::array<Truth, 5> kTruth = {{
    {"reach/d1_arm_fraction", 0.62, 0.64, 0.5, 1.2},
    {"reach/d2_height_fraction", 0.42, 0.43, 0.3, 0.6},
    {"reach/d3_height_fraction", 0.70, 0.68, 0.5, 0.9},
    {"guidance/kappa", 300.0, 315.0, 50.0, 2000.0},
    {"fatigue/a_max", 25000.0, 24000.0, 5000.0, 1e6},
}};

constexpr int kRepetitions = 6;        // per operator in the lab
constexpr int kLabSegmentCycles = 10;  // per segment of the lab's hour
constexpr int kVirtualTrials = 10;     // per operator and segment, per evaluation
const scene::FatigueDesign kHour = {60.0, 4, 4};

experiment::RunnerOptions Quiet() { return testing::QuietRunner(); }

SyntheticLabSpec CoverageLab(std::uint64_t seed) {
  SyntheticLabSpec spec;
  spec.file = "coverage_test";
  spec.name = "coverage";
  spec.scene = scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  for (const Truth& t : kTruth) {
    scene::FindParam(t.name)->real(spec.scene.params) = t.value;
    spec.truth.emplace_back(t.name, t.value);
  }
  EXPECT_EQ(scene::ParameterViolation(spec.scene), "");
  // GB/T 10000-1988's P5, P50 and P95 men and women, and two whose arms are
  // long or short for their stature: D1 (arm) and D2 (stature) then fall
  // at different distances of the block's path for each, which sets their
  // effects on the times apart from kappa's, the same for all.
  spec.operators = {{"female P5", "female", 1.484, 0.614, ""},
                    {"female P50", "female", 1.570, 0.668, ""},
                    {"female P95", "female", 1.659, 0.723, ""},
                    {"male P5", "male", 1.583, 0.675, ""},
                    {"male P50", "male", 1.678, 0.733, ""},
                    {"male P95", "male", 1.775, 0.792, ""},
                    {"long arms", "male", 1.62, 0.80, ""},
                    {"short arms", "female", 1.72, 0.62, ""}};
  spec.repetitions = kRepetitions;
  spec.seed = seed;
  spec.time_sd = 0.02;
  spec.time_resolution = 0.001;
  spec.condition = "standard";
  spec.fatigue.design = kHour;
  spec.fatigue.trials = kLabSegmentCycles;
  return spec;
}

CalibrationSpec JointFit() {
  CalibrationSpec spec;
  spec.stages.emplace_back();
  StageSpec& stage = spec.stages[0];
  for (std::size_t i = 0; i < kTruth.size(); ++i) {
    const Truth& t = kTruth[i];
    stage.parameters.push_back(
        {t.name, t.start, t.lower, t.upper, "/parameters/" + std::to_string(i), ""});
  }
  // Each operator's mean time, weighed by the variance pooled over the 8
  // operators (40 degrees of freedom on the lab's side, 72 on the virtual):
  // an operator's own from 6 lab times made the whitened residuals t-like
  // and the intervals about 10 % narrow (docs/calibration.md, Pooled
  // variances).
  stage.targets.push_back({"assembly_time", "block", true, "/targets/0", 0, 0, ""});
  stage.targets.back().pooled_variance = true;
  for (int s = 2; s <= kHour.segments; ++s) {
    TargetSpec t;
    t.quantity = "success_rate";
    t.part = kAllParts;
    t.segment = s;
    t.pointer = "/targets/" + std::to_string(s - 1);
    stage.targets.push_back(t);
  }
  spec.fatigue = kHour;
  spec.noise_replicates = 0;
  spec.relative_step = 0.1;
  spec.max_iterations = 8;
  // The model is the lab: no outliers to down-weight, and a robust loss
  // would bend the covariance away from the least-squares one under test.
  spec.loss = "none";
  spec.intervals = "profile";
  // The fits stay inside their bounds: Ceres' line search on them took
  // most of the design evaluations (docs/calibration.md, Solvers).
  spec.line_search = false;
  return spec;
}

// The smallest count c with P(X < c) <= alpha for X ~ Binomial(n, p): with
// intervals that cover with probability p, fewer than c covered happens
// with probability alpha at most.
int BinomialLowerBound(int n, double p, double alpha) {
  double below = 0;  // P(X < c)
  for (int c = 0; c <= n; ++c) {
    const double pc =
        std::exp(std::lgamma(n + 1.0) - std::lgamma(c + 1.0) - std::lgamma(n - c + 1.0) +
                 c * std::log(p) + (n - c) * std::log1p(-p));
    if (below + pc > alpha) return c;
    below += pc;
  }
  return n;
}

struct Tally {
  int identified = 0, not_identified = 0, covered = 0, no_interval = 0;
  int wald_covered = 0;  // by the Wald interval, for comparison
  // The profile interval's half-width / 1.96: the standard error it implies.
  std::vector<double> estimates, standard_errors, wald_standard_errors;
};

double Mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? std::nan("") : s / static_cast<double>(v.size());
}

double Sd(const std::vector<double>& v) {
  if (v.size() < 2) return std::nan("");
  const double m = Mean(v);
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}

// The squared Mahalanobis distance of the estimate from the truth over the
// identified parameters with an interval, (x - t)^T C^-1 (x - t), and how
// many there are: with a right joint covariance it is chi^2 with that many
// degrees of freedom. -1 when the covariance of those is not positive.
double Mahalanobis(const CalibrationResult& r, int* dof) {
  std::vector<Eigen::Index> keep;
  for (std::size_t i = 0; i < r.parameters.size(); ++i)
    if (r.parameters[i].identified && std::isfinite(r.parameters[i].standard_error))
      keep.push_back(static_cast<Eigen::Index>(i));
  *dof = static_cast<int>(keep.size());
  const Eigen::Index k = static_cast<Eigen::Index>(keep.size());
  Eigen::MatrixXd c(k, k);
  Eigen::VectorXd e(k);
  for (Eigen::Index a = 0; a < k; ++a) {
    const std::size_t i = static_cast<std::size_t>(keep[static_cast<std::size_t>(a)]);
    e(a) = r.parameters[i].estimate - kTruth[i].value;
    for (Eigen::Index b = 0; b < k; ++b)
      c(a, b) = r.covariance(keep[static_cast<std::size_t>(a)],
                             keep[static_cast<std::size_t>(b)]);
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(c);
  if (llt.info() != Eigen::Success) return -1;
  return e.dot(llt.solve(e));
}

// The p-quantile of chi^2 with k degrees of freedom (Wilson and Hilferty
// 1931; within 1 % of the exact for k >= 5 in the tails used here), z the
// standard normal quantile of p.
double ChiSquareQuantile(int k, double z) {
  const double a = 2.0 / (9.0 * k);
  return k * std::pow(1 - a + z * std::sqrt(a), 3);
}

// At the CI size (datasets 0-2: dataset 0's data pull d2 and kappa away
// from the truth, docs/calibration.md, "Joint coverage") the binomial bound
// tolerates one miss of three per parameter; it fails when the intervals
// are far too narrow, as the Wald ones were. The full size's figures are in
// that section.
TEST(Coverage, JointIntervalsOfReachKappaAndAmaxHoldTheTruth) {
  const char* env = std::getenv("VAHF_COVERAGE_DATASETS");
  const bool full = env != nullptr;
  const int datasets = full ? std::max(1, std::atoi(env)) : 3;
  // VAHF_COVERAGE_FIRST=K starts at dataset K, so that a full run can be
  // split (its CSVs concatenated; the checks then need the whole).
  const char* first_env = std::getenv("VAHF_COVERAGE_FIRST");
  const int first = first_env ? std::max(0, std::atoi(first_env)) : 0;
  const char* csv_path = std::getenv("VAHF_COVERAGE_CSV");
  const bool verbose = std::getenv("VAHF_COVERAGE_VERBOSE") != nullptr;
  std::ofstream csv;
  if (csv_path) {
    csv.open(csv_path);
    csv << "dataset,parameter,truth,estimate,standard_error,wald_lower,wald_upper,"
           "profile_lower,profile_upper,identified,covers,wald_covers,evaluations,"
           "seconds\n";
  }
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const CalibrationSpec spec = JointFit();
  std::vector<Tally> tally(kTruth.size());
  double seconds = 0;
  double distance = 0;  // sum of the datasets' squared Mahalanobis distances
  int dof = 0, bad_covariance = 0;
  for (int d = first; d < first + datasets; ++d) {
    const data::LabDataset lab =
        GenerateSyntheticLab(CoverageLab(5000 + static_cast<std::uint64_t>(d)), Quiet());
    ASSERT_EQ(lab.segments.size(), static_cast<std::size_t>(kHour.segments));
    const std::vector<CalibrationResult> stages =
        Calibrate(scene, lab, spec, "coverage_test", 9000 + static_cast<std::uint64_t>(d),
                  kVirtualTrials, Quiet(), [&](const std::string& line) {
                    if (verbose) std::puts(line.c_str());
                  });
    ASSERT_EQ(stages.size(), 1u);
    const CalibrationResult& r = stages[0];
    seconds += r.seconds;
    if (verbose) {
      std::printf("%s\n%s\n", r.ceres_brief.c_str(), r.ceres_full.c_str());
      for (const FittedTarget& t : r.targets)
        std::printf(
            "  %-45s lab %.4g (sd %.3g)  start %.4g  fit %.4g (sd %.3g)  r %.2f\n",
            t.target.label.c_str(), t.target.lab.value, std::sqrt(t.target.lab.variance),
            t.start.value, t.fitted.value, std::sqrt(t.fitted.variance), t.residual);
      for (const FittedParameter& f : r.parameters) {
        std::printf("  profile of %s:", f.name.c_str());
        for (const auto& [v, rise] : f.profile_points)
          std::printf(" (%.5g, %.3g)", v, rise);
        std::printf("\n");
      }
    }
    int k = 0;
    const double d2 = Mahalanobis(r, &k);
    if (d2 < 0) {
      ++bad_covariance;
    } else {
      distance += d2;
      dof += k;
    }
    std::printf(
        "dataset %d: %d evaluations, %.1f s, rank %d, squared distance %.2f on %d\n", d,
        r.evaluations, r.seconds, r.rank.rank, d2, k);
    for (std::size_t i = 0; i < kTruth.size(); ++i) {
      const FittedParameter& f = r.parameters[i];
      const double truth = kTruth[i].value;
      const bool has_interval = f.identified && f.has_profile && f.profile_reached;
      const bool covers =
          has_interval && f.profile.lower <= truth && truth <= f.profile.upper;
      const bool wald_covers = f.identified && f.ci.lower <= truth && truth <= f.ci.upper;
      Tally& t = tally[i];
      if (!f.identified) {
        ++t.not_identified;
      } else {
        ++t.identified;
        t.covered += covers;
        t.wald_covered += wald_covers;
        t.no_interval += !has_interval;
        t.estimates.push_back(f.estimate);
        if (has_interval)
          t.standard_errors.push_back((f.profile.upper - f.profile.lower) / (2 * 1.96));
        if (std::isfinite(f.standard_error))
          t.wald_standard_errors.push_back(f.standard_error);
      }
      std::printf(
          "  %-26s %10.5g  se %9.3g  Wald [%10.5g, %10.5g]  profile [%10.5g, %10.5g]  "
          "%s\n",
          f.name.c_str(), f.estimate, f.standard_error, f.ci.lower, f.ci.upper,
          f.profile.lower, f.profile.upper,
          !f.identified ? "not identified"
          : covers      ? "holds"
                        : "misses");
      if (csv_path)
        csv << d << ',' << f.name << ',' << truth << ',' << f.estimate << ','
            << f.standard_error << ',' << f.ci.lower << ',' << f.ci.upper << ','
            << f.profile.lower << ',' << f.profile.upper << ',' << f.identified << ','
            << covers << ',' << wald_covers << ',' << r.evaluations << ',' << r.seconds
            << '\n';
    }
    csv.flush();
    std::fflush(stdout);
  }
  std::printf("\n%d datasets, %.1f s of fitting (%.1f s per fit)\n", datasets, seconds,
              seconds / datasets);
  std::printf("%-26s %9s %7s %9s %10s %10s %10s %10s %10s %12s\n", "parameter", "truth",
              "not id.", "covered", "coverage", "mean est.", "profile se", "sd of est.",
              "Wald se", "Wald covered");
  for (std::size_t i = 0; i < kTruth.size(); ++i) {
    const Tally& t = tally[i];
    std::printf("%-26s %9.5g %7d %4d of %-2d %9.1f%% %10.5g %10.4g %10.4g %10.4g %12d\n",
                kTruth[i].name, kTruth[i].value, t.not_identified, t.covered,
                t.identified,
                t.identified ? 100.0 * t.covered / t.identified : std::nan(""),
                Mean(t.estimates), Mean(t.standard_errors), Sd(t.estimates),
                Mean(t.wald_standard_errors), t.wald_covered);
  }
  // The Wald covariance's joint check, printed, not asserted: on this
  // design it is too narrow (the ridge; docs/calibration.md, Joint
  // coverage), which is why the intervals under test are the profile ones.
  const double low = ChiSquareQuantile(dof, -3.09), high = ChiSquareQuantile(dof, 3.09);
  std::printf(
      "Wald covariance: sum of squared Mahalanobis distances %.2f on %d degrees of "
      "freedom (99.8 %% of chi^2: [%.1f, %.1f]); %d without a positive covariance\n",
      distance, dof, low, high, bad_covariance);
  for (std::size_t i = 0; i < kTruth.size(); ++i) {
    const Tally& t = tally[i];
    const std::string name = kTruth[i].name;
    // kappa and A_max: every dataset determines them.
    if (name == "guidance/kappa" || name == "fatigue/a_max") {
      EXPECT_EQ(t.not_identified, 0) << name;
    }
    if (t.identified == 0) continue;
    // At 95 %, fewer than this many covered happens with probability 1 %
    // at most; at full size, the line: 90 % or more.
    const int need = full ? static_cast<int>(std::ceil(0.9 * t.identified))
                          : BinomialLowerBound(t.identified, 0.95, 0.01);
    EXPECT_GE(t.covered, need) << name << ": " << t.covered << " of " << t.identified;
    EXPECT_EQ(t.no_interval, 0) << name;
    // The profile intervals' implied standard errors are the estimates'
    // spread: intervals too narrow or too wide by a factor of two fail.
    if (t.estimates.size() >= 5) {
      const double ratio = Mean(t.standard_errors) / Sd(t.estimates);
      EXPECT_GT(ratio, 0.5) << name << ": mean se against the estimates' sd";
      EXPECT_LT(ratio, 2.0) << name << ": mean se against the estimates' sd";
    }
  }
}

}  // namespace
}  // namespace vahf::calibrate
