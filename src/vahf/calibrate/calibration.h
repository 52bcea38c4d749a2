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
//
// Solvers: Ceres' Levenberg-Marquardt, or for one parameter whose objective
// is piecewise constant (a success rate over a few cycles) a bracketed
// golden-section search on the same cost (bracketed_search.h), after which Ceres
// computes the covariance at the estimate all the same.
//
// Stages: a calibration may fit in stages, each stage's parameters to its own
// targets, on the scene with every earlier stage's estimates. The
// covariance is then per stage: an earlier estimate's uncertainty is not
// carried into a later stage's interval (the report says so).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "vahf/calibrate/calibration_input.h"
#include "vahf/calibrate/feasible_difference.h"
#include "vahf/calibrate/identifiability.h"
#include "vahf/calibrate/targets.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/experiment/runner.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/scene.h"
#include "vahf/stats/summary.h"

namespace vahf::calibrate {

using ParameterSpec = FitParameter;
using CalibrationSpec = CalibrationDesign;
using StageSpec = CalibrationStage;
// Rounds of re-weighting (see above).
inline constexpr int kMaxRounds = 3;
// chi^2 with one degree of freedom at 0.95 (3.841459, gsl_cdf_chisq_Pinv),
// halved: the rise of a cost of 1/2 sum r^2 that bounds the 95 % profile
// interval.
double ProfileRise();
// Two-sided 95 % normal quantile, for intervals from the covariance.
inline constexpr double kZ95 = 1.959963984540054;

// The scene with `values` (one per spec parameter) set. Values that break a
// rule tying parameters together (D1 < D2 < D3, say) are an InputError naming
// `experiment_file`'s parameters: their bounds admit a scene that is not one.
scene::Scene WithParameters(const scene::Scene& scene,
                            const std::vector<ParameterSpec>& params,
                            const std::vector<double>& values,
                            const std::string& experiment_file);

struct FittedParameter {
  std::string name;
  double scene_value = 0;  // in the scene before this stage: what the fit replaces
  double start = 0, estimate = 0;
  double standard_error = 0;  // NaN when the covariance is rank deficient
  stats::Interval ci;         // estimate +- 1.96 standard errors (normal)
  // The golden_section solver's cost is piecewise constant, where a
  // covariance from its slope at the estimate says little: its stage also
  // gives the profile interval (ProfileBounds, rise chi^2_1(0.95) / 2), each
  // end open (the parameter's bound) when the cost stays within the rise up
  // to it.
  // A Levenberg-Marquardt stage with "intervals": "profile" gives each
  // identified parameter its profile interval too, the others re-fitted
  // (profile_likelihood.h); `profile_points` are the (value, rise) it
  // evaluated, the estimate's (0) included, in increasing value, and
  // `profile_reached` is false where an end's search ran out of calls
  // inside the rise (that end is then too near the estimate).
  bool has_profile = false;
  stats::Interval profile;
  bool profile_open_lower = false, profile_open_upper = false;
  bool profile_reached = true;
  std::vector<std::pair<double, double>> profile_points;
  // Whether the targets determine it (identifiability.h); when not, why,
  // and it has no standard error or interval.
  bool identified = true;
  std::string not_identified_why;
  // Levenberg-Marquardt stages: the cost's rise from the estimate to each
  // end of the valid region along this parameter (the others held), and
  // where that end is (the bound, or where a rule stops it first).
  double rise_lower = std::nan(""), rise_upper = std::nan("");
  double edge_lower = std::nan(""), edge_upper = std::nan("");
  // The cost's rise along this parameter alone (value, rise), in increasing
  // value, the estimate's (0) included: its scan to either end.
  std::vector<std::pair<double, double>> scan;
  // The estimate's Monte Carlo spread over other virtual people (a
  // Levenberg-Marquardt stage of the lab's operators; NaN otherwise): the
  // part of its uncertainty the virtual trials' noise makes.
  double mc_sd = std::nan("");
  // A start an override file gave (FitParameter::start_from; a calibration
  // started from its own estimate): whether the fit returned to it, by the
  // solver's own tolerance (kFixedPointTolerance); NaN otherwise.
  std::string start_from;
  double fixed_point_change = std::nan("");     // |estimate - start|
  double fixed_point_tolerance = std::nan("");  // what the solver would not resolve
};

// The fixed point's tolerance (docs/calibration.md, "A fixed point"): a
// golden_section stage's bracket width, `tolerance` times the estimate. A
// Levenberg-Marquardt stage's is the larger of Ceres' parameter tolerance
// (this fraction of the norm of the stage's parameter vector) and a tenth
// of the parameter's standard error: its weights are evaluated at its start
// and settle to 10 % (calibration.cc, WeightsSettled), so a fit started
// at its own estimate re-weighs and may move by a small part of what the
// data resolve (measured on calibrate_synthetic: 0.02 standard errors).
inline constexpr double kLevenbergMarquardtParameterTolerance = 1e-4;
inline constexpr double kFixedPointStandardErrors = 0.1;

struct FittedTarget {
  Target target;
  Statistic start;      // virtual, at the start vector
  Statistic fitted;     // virtual, at the estimate
  double residual = 0;  // (fitted - lab) / sigma at the estimate
};

// The result of one stage.
struct CalibrationResult {
  std::string stage;   // its name ("" for a file of one stage)
  std::string solver;  // "levenberg_marquardt" or "golden_section"
  std::vector<FittedParameter> parameters;
  Eigen::MatrixXd covariance;  // of the estimate, in the parameters' units
  // A covariance was computed: Ceres' of all parameters, or, when some are
  // not identified, that of the others with those held (identifiability.h).
  bool covariance_ok = false;
  Eigen::MatrixXd correlation;   // of the covariance; NaN where it has none
  JacobianRank rank;             // of the whitened Jacobian at the estimate
  DifferenceCounts differences;  // how the Jacobians were differenced
  Eigen::MatrixXd jacobian;      // whitened, at the estimate (Levenberg-Marquardt)
  int noise_replicates = 0;      // replicates behind FittedParameter::mc_sd
  int refused = 0;               // points outside the valid region the solver asked for
  // The least rise a profile re-fit found above the estimate's cost: below
  // 0, a point of lower cost than the estimate, which the fit stopped short
  // of (its intervals are then measured from too high a cost).
  double profile_least_rise = 0;
  std::vector<FittedTarget> targets;
  bool converged = false;  // Ceres reported convergence in the last round
  int rounds = 0;
  int evaluations = 0;      // virtual designs run (each `trials` cycles per condition)
  double final_cost = 0;    // 1/2 sum of robustified squared residuals
  std::string ceres_brief;  // Summary::BriefReport of each round (LM), or the search's
  std::string ceres_full;   // Summary::FullReport of the last round (LM)
  std::string search_log;   // golden_section: the walk and each iteration, every round
  double seconds = 0;       // wall time of the stage
};

// Progress: one line per design evaluation and per Ceres iteration.
using CalibrationProgress = std::function<void(const std::string& line)>;

// Fits one stage of `spec` to `lab` on `scene`: each evaluation runs
// LabConditions (or, for segment targets, the fatigue design) with `trials`
// cycles each from cycle 0 with `seed` on `options.threads` threads. The same
// inputs give the same bits whatever the thread count.
CalibrationResult CalibrateStage(const scene::Scene& scene, const data::LabDataset& lab,
                                 const CalibrationSpec& spec, const StageSpec& stage,
                                 const std::string& experiment_file, std::uint64_t seed,
                                 int trials, const experiment::RunnerOptions& options,
                                 const CalibrationProgress& progress = {});

// Every stage in order, each on the scene with the earlier stages' estimates.
std::vector<CalibrationResult> Calibrate(
    const scene::Scene& scene, const data::LabDataset& lab, const CalibrationSpec& spec,
    const std::string& experiment_file, std::uint64_t seed, int trials,
    const experiment::RunnerOptions& options, const CalibrationProgress& progress = {});

// `scene` with every stage's estimates set.
scene::Scene WithEstimates(const scene::Scene& scene,
                           const std::vector<CalibrationResult>& stages);

}  // namespace vahf::calibrate
