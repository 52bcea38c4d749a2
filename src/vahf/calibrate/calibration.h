// Calibration of model parameters against lab summaries by Ceres nonlinear
// least squares (docs/calibration.md).
//
// Each target contributes one residual, (virtual - lab) / sigma, with
// sigma^2 the lab statistic's variance plus the virtual one's: the residuals
// are whitened, so Ceres' covariance of the fit, (J^T J)^-1, is the
// covariance of the estimate without further scaling (the delta method). The
// virtual statistics come from the same keys at every parameter vector
// (common random numbers: seed and cycle indices fixed), so the objective is
// a fixed function of the parameters rather than a fresh sample at each
// call, and finite differences measure its slope rather than its noise. The
// slope is still taken over a relative step large against a single trial's
// switches of branch (CalibrationSpec::relative_step, central differences).
//
// The weights sigma are evaluated at the start vector, the problem solved,
// then re-evaluated at the fit and solved again from there until they change
// by under 10 % (at most kMaxRounds): the covariance is that of the last
// round, with sigma at the estimate.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "vahf/calibrate/targets.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/experiment/runner.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/scene.h"
#include "vahf/stats/summary.h"

namespace vahf::calibrate {

using ParameterSpec = scene::FitParameter;
using CalibrationSpec = scene::CalibrationDesign;
// Rounds of re-weighting (see above).
inline constexpr int kMaxRounds = 3;

// The scene with `values` (one per spec parameter) set. Values that break a
// rule tying parameters together (D1 < D2 < D3, say) are an InputError naming
// `experiment_file`'s parameters: their bounds admit a scene that is not one.
scene::Scene WithParameters(const scene::Scene& scene, const std::vector<ParameterSpec>& params,
                            const std::vector<double>& values,
                            const std::string& experiment_file);

struct FittedParameter {
  std::string name;
  double start = 0, estimate = 0;
  double standard_error = 0;  // NaN when the covariance is rank deficient
  stats::Interval ci;         // estimate +- 1.96 standard errors (normal)
};

struct FittedTarget {
  Target target;
  Statistic start;     // virtual, at the start vector
  Statistic fitted;    // virtual, at the estimate
  double residual = 0;  // (fitted - lab) / sigma at the estimate
};

struct CalibrationResult {
  std::vector<FittedParameter> parameters;
  Eigen::MatrixXd covariance;  // of the estimate, in the parameters' units
  bool covariance_ok = false;  // Ceres computed it (the problem is not rank deficient)
  std::vector<FittedTarget> targets;
  bool converged = false;  // Ceres reported convergence in the last round
  int rounds = 0;
  int evaluations = 0;     // virtual designs run (each `trials` cycles per condition)
  double final_cost = 0;   // 1/2 sum of robustified squared residuals
  std::string ceres_brief;  // Summary::BriefReport of each round
  std::string ceres_full;   // Summary::FullReport of the last round
};

// Progress: one line per design evaluation and per Ceres iteration.
using CalibrationProgress = std::function<void(const std::string& line)>;

// Fits `spec` to `lab` on `scene`: each evaluation runs LabConditions with
// `trials` cycles each from cycle 0 with `seed` on `options.threads`
// threads. The same inputs give the same bits whatever the thread count.
CalibrationResult Calibrate(const scene::Scene& scene, const data::LabDataset& lab,
                            const CalibrationSpec& spec, const std::string& experiment_file,
                            std::uint64_t seed, int trials,
                            const experiment::RunnerOptions& options,
                            const CalibrationProgress& progress = {});

}  // namespace vahf::calibrate
