#include "vahf/calibrate/calibration.h"

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "vahf/calibrate/bracketed_search.h"
#include "vahf/calibrate/feasible_difference.h"
#include "vahf/calibrate/identifiability.h"
#include "vahf/calibrate/internal/stage_profile.h"
#include "vahf/calibrate/internal/virtual_model.h"
#include "vahf/core/error.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::calibrate {
namespace {

const double kProfileRise = ProfileRise();

// One target's whitened residual at a fixed weight. Each target is its own
// residual block, so that the robust loss weighs each target by its own
// residual, not by the norm of all.
struct Residual {
  VirtualModel* model;
  const Target* target;
  std::size_t index;
  double sigma;
  bool operator()(const double* x, double* residual) const {
    const Statistic& v = model->At(x)[index];
    if (!std::isfinite(v.value)) return false;  // no sample: Ceres steps back
    residual[0] = (v.value - target->lab.value) / sigma;
    return true;
  }
};

// sigma_i = sqrt(lab variance + virtual variance) at the virtual statistics `v`.
std::vector<double> Weights(const std::vector<Target>& targets,
                            const std::vector<Statistic>& v, const std::string& where) {
  std::vector<double> sigma;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const double var = LabVariance(targets[i].lab, v[i]) + v[i].variance;
    if (!std::isfinite(v[i].value) || !(std::isfinite(var) && var > 0))
      throw ComputationError(
          ComputationError::Reason::kTooFewValues,
          fmt::format(
              "calibration: the virtual design at {} gives no usable {} ({} samples): "
              "too few completed trials to weigh this target; widen `trials` or change "
              "the start",
              where, targets[i].label, v[i].n));
    sigma.push_back(std::sqrt(var));
  }
  return sigma;
}

// Whether the weights at the fit, `refit`, are within 10 % of the round's:
// else the next round re-weighs.
bool WeightsSettled(const std::vector<double>& refit, const std::vector<double>& sigma) {
  for (std::size_t i = 0; i < sigma.size(); ++i)
    if (!(std::abs(refit[i] / sigma[i] - 1) < 0.1)) return false;
  return true;
}

}  // namespace

double ProfileRise() { return 0.5 * gsl_cdf_chisq_Pinv(0.95, 1.0); }

scene::Scene WithParameters(const scene::Scene& scene,
                            const std::vector<ParameterSpec>& params,
                            const std::vector<double>& values,
                            const std::string& experiment_file) {
  VAHF_CHECK(params.size() == values.size(), "one value per fitted parameter");
  scene::Scene out = scene;
  SetParameters(params, values.data(), &out);
  const std::string violation = scene::ParameterViolation(out);
  if (!violation.empty()) {
    std::string text;
    for (std::size_t i = 0; i < params.size(); ++i)
      text += fmt::format("{}{} = {:.6g}", i ? ", " : "", params[i].name, values[i]);
    throw InputError(experiment_file, "/parameters", text,
                     "the bounds admit parameter values that break a rule of scene '" +
                         scene.name + "': " + violation + "; narrow the bounds");
  }
  return out;
}

namespace {

// The stage's problem at `x`: one residual block per target, bounds.
void BuildProblem(ceres::Problem* problem, VirtualModel* model,
                  const CalibrationSpec& spec, const StageSpec& stage,
                  const std::vector<Target>& targets, const std::vector<double>& sigma,
                  const std::shared_ptr<DifferenceCounts>& counts, double* x) {
  const int p = static_cast<int>(stage.parameters.size());
  const auto valid = [model](const double* v) { return model->Violation(v).empty(); };
  for (std::size_t i = 0; i < targets.size(); ++i) {
    // The problem takes ownership of the cost function.
    problem->AddResidualBlock(
        MakeFeasibleDifferenceCost(p, 1, spec.relative_step,
                                   Residual{model, &targets[i], i, sigma[i]}, valid,
                                   counts)
            .release(),
        MakeLoss(spec), x);
  }
  for (int i = 0; i < p; ++i) {
    problem->SetParameterLowerBound(x, i,
                                    stage.parameters[static_cast<std::size_t>(i)].lower);
    problem->SetParameterUpperBound(x, i,
                                    stage.parameters[static_cast<std::size_t>(i)].upper);
  }
}

// One round of the golden_section solver on the round's weights `sigma`:
// moves x[0] to the search's estimate and keeps its bracket for the next
// round. Returns the round's one-line report.
std::string GoldenSectionRound(VirtualModel& model, const std::vector<Target>& targets,
                               const std::vector<double>& sigma,
                               const CalibrationSpec& spec, const StageSpec& stage,
                               int round, std::vector<double>* x,
                               std::optional<std::array<double, 3>>* bracket,
                               CalibrationResult* out) {
  const ParameterSpec& ps = stage.parameters[0];
  const BracketedSearch search = MinimizeBracketed(
      [&](double v) { return Cost(model, targets, sigma, spec, &v); }, ps.lower, ps.upper,
      (*x)[0], spec.tolerance, spec.max_iterations, *bracket);
  (*x)[0] = search.estimate;
  *bracket = search.bracket;
  out->search_log += fmt::format("round {}:\n{}", round, search.log);
  out->converged = search.converged;
  out->final_cost = search.cost;
  return fmt::format(
      "golden section (GSL): {} iterations, cost {:.6g}, bracket [{:.6g}, {:.6g}]{}",
      search.iterations, search.cost, search.bracket[0], search.bracket[2],
      search.at_bound    ? ", the cost still falls at a bound"
      : search.converged ? ", converged"
                         : ", not converged");
}

// One round of Ceres' Levenberg-Marquardt on `problem` (which moves its
// parameter block). Returns the round's one-line report.
std::string LevenbergMarquardtRound(const CalibrationSpec& spec, ceres::Problem* problem,
                                    CalibrationResult* out) {
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = spec.max_iterations;
  solver.num_threads = 1;  // parallel inside each evaluation instead
  // A relative change of 1e-4 in the parameters is far below what the
  // Monte Carlo noise of a design resolves.
  solver.parameter_tolerance = kLevenbergMarquardtParameterTolerance;
  // Ceres runs a projected line search on the bounds after every step of a
  // bounded problem (solver.h); each of its steps takes a gradient, one
  // differenced Jacobian, 2 p + 1 designs here. Measured on the joint
  // coverage fit (dataset 3, 5 parameters): 36 line-search steps in one
  // round, 396 of its 407 design evaluations, for 2 accepted steps. Off,
  // a step is projected onto the bounds (docs/calibration.md, Solvers).
  if (!spec.line_search) solver.max_num_line_search_step_size_iterations = 0;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, problem, &summary);
  out->ceres_full = summary.FullReport();
  out->converged = summary.termination_type == ceres::CONVERGENCE;
  out->final_cost = summary.final_cost;
  return summary.BriefReport();
}

// The covariance of `problem` at the estimate x (p parameters): NaN where
// Ceres cannot compute it or it is not positive.
void EstimateCovariance(ceres::Problem* problem, const std::vector<double>& x, int p,
                        CalibrationResult* out) {
  ceres::Covariance::Options cov_options;
  cov_options.algorithm_type = ceres::DENSE_SVD;
  ceres::Covariance covariance(cov_options);
  out->covariance = Eigen::MatrixXd::Constant(p, p, std::nan(""));
  const std::vector<const double*> blocks = {x.data()};
  if (covariance.Compute(blocks, problem)) {
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> c(p, p);
    out->covariance_ok = covariance.GetCovarianceMatrix(blocks, c.data()) &&
                         c.allFinite() && (c.diagonal().array() > 0).all();
    if (out->covariance_ok) out->covariance = c;
  }
}

// The whitened residuals' Jacobian of `problem` at its parameters (m x p,
// robustified as the solver sees it), differenced as the solver's were;
// NaN when it cannot be evaluated.
Eigen::MatrixXd JacobianOf(ceres::Problem* problem, int m, int p) {
  ceres::CRSMatrix crs;
  double cost = 0;
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(m, p);
  if (!problem->Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr,
                         &crs) ||
      crs.num_rows != m || crs.num_cols != p)
    return Eigen::MatrixXd::Constant(m, p, std::nan(""));
  for (int r = 0; r < crs.num_rows; ++r)
    for (int k = crs.rows[static_cast<std::size_t>(r)];
         k < crs.rows[static_cast<std::size_t>(r) + 1]; ++k)
      j(r, crs.cols[static_cast<std::size_t>(k)]) =
          crs.values[static_cast<std::size_t>(k)];
  return j;
}

// How far parameter i may move from the estimate x toward `bound` within
// the valid region (a rule such as D1 < D2 < D3 may stop it first): the
// bound, or the valid side of the region's edge found by bisection.
double EdgeToward(const VirtualModel& model, std::vector<double> x, std::size_t i,
                  double bound) {
  const double from = x[i];
  x[i] = bound;
  if (model.Violation(x.data()).empty()) return bound;
  double valid = from, invalid = bound;
  for (int k = 0; k < 60 && valid != invalid; ++k) {
    x[i] = 0.5 * (valid + invalid);
    if (x[i] == valid || x[i] == invalid) break;
    (model.Violation(x.data()).empty() ? valid : invalid) = x[i];
  }
  return valid;
}

// Points of the cost's scan along each parameter on either side of the
// estimate (docs/calibration.md, Identifiability): enough to draw its shape.
constexpr int kScanPoints = 3;

// Which parameters of a Levenberg-Marquardt stage the targets determine
// (identifiability.h), and the covariance that follows: Ceres' of all when
// every one is, else that of the identified ones with the others held.
std::vector<FittedParameter> Identify(VirtualModel& model, ceres::Problem* problem,
                                      const std::vector<Target>& targets,
                                      const std::vector<double>& sigma,
                                      const CalibrationSpec& spec, const StageSpec& stage,
                                      const std::vector<double>& x,
                                      CalibrationResult* out) {
  const int p = static_cast<int>(stage.parameters.size());
  const Eigen::MatrixXd j = JacobianOf(problem, static_cast<int>(targets.size()), p);
  Eigen::VectorXd scale(p);
  for (int i = 0; i < p; ++i) {
    const ParameterSpec& ps = stage.parameters[static_cast<std::size_t>(i)];
    const double v = std::abs(x[static_cast<std::size_t>(i)]);
    scale(i) = v > 0 ? v : ps.upper - ps.lower;
  }
  out->rank = RankOf(j, scale);
  out->jacobian = j;
  std::vector<FittedParameter> fitted(static_cast<std::size_t>(p));
  std::vector<bool> identified(static_cast<std::size_t>(p));
  const double at_estimate = Cost(model, targets, sigma, spec, x.data());
  for (std::size_t i = 0; i < identified.size(); ++i) {
    FittedParameter& f = fitted[i];
    const ParameterSpec& ps = stage.parameters[i];
    // The cost along parameter i alone, at kScanPoints points from the
    // estimate to each end of its valid range, the last at the end.
    const auto rise = [&](double bound, double* edge) {
      *edge = EdgeToward(model, x, i, bound);
      if (*edge == x[i]) return 0.0;
      std::vector<double> at = x;
      double last = 0;
      for (int k = 1; k <= kScanPoints; ++k) {
        at[i] = k == kScanPoints ? *edge : x[i] + (*edge - x[i]) * k / kScanPoints;
        last = Cost(model, targets, sigma, spec, at.data()) - at_estimate;
        f.scan.emplace_back(at[i], last);
      }
      return last;
    };
    f.scan.emplace_back(x[i], 0.0);
    f.rise_lower = rise(ps.lower, &f.edge_lower);
    f.rise_upper = rise(ps.upper, &f.edge_upper);
    std::sort(f.scan.begin(), f.scan.end());
    if (out->rank.in_null_space[i]) {
      f.identified = false;
      f.not_identified_why =
          "no target moves it within a difference step of the estimate (the whitened "
          "Jacobian's null space)";
    } else if (f.rise_lower < kProfileRise && f.rise_upper < kProfileRise) {
      f.identified = false;
      f.not_identified_why = fmt::format(
          "the cost rises by less than {:.2f} from the estimate to either end of its "
          "range [{:.6g}, {:.6g}] ({:.3g} and {:.3g}): the targets do not bound it there",
          kProfileRise, f.edge_lower, f.edge_upper, f.rise_lower, f.rise_upper);
    }
    identified[i] = f.identified;
  }
  if (std::all_of(identified.begin(), identified.end(), [](bool b) { return b; })) {
    EstimateCovariance(problem, x, p, out);
    if (out->covariance_ok) return fitted;
  }
  out->covariance = ConditionalCovariance(j, scale, identified);
  out->covariance_ok = false;
  for (int i = 0; i < p; ++i)
    out->covariance_ok = out->covariance_ok || std::isfinite(out->covariance(i, i));
  return fitted;
}

// The Monte Carlo spread of the estimate: on each of `replicates` other sets
// of virtual people (VirtualModel::Replicate), the Gauss-Newton step from the
// estimate that the replicate's residuals call for, -J_I^+ (r_k - r), over
// the identified parameters I; the root mean square of those steps. Since
// J^T r = 0 at the estimate, the step is how far the fit would move on those
// draws. Only for a design of the lab's operators.
void MonteCarloSpread(VirtualModel& model, const std::vector<double>& sigma,
                      const std::vector<double>& x, int replicates,
                      CalibrationResult* out, std::vector<FittedParameter>* fitted) {
  if (replicates <= 0 || !model.lab_design() || !out->jacobian.allFinite()) return;
  std::vector<Eigen::Index> keep;
  for (std::size_t i = 0; i < fitted->size(); ++i)
    if ((*fitted)[i].identified) keep.push_back(static_cast<Eigen::Index>(i));
  if (keep.empty()) return;
  const Eigen::Index m = out->jacobian.rows();
  Eigen::MatrixXd j(m, static_cast<Eigen::Index>(keep.size()));
  for (std::size_t c = 0; c < keep.size(); ++c)
    j.col(static_cast<Eigen::Index>(c)) = out->jacobian.col(keep[c]);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(j,
                                              Eigen::ComputeThinU | Eigen::ComputeThinV);
  const std::vector<Statistic> base = model.At(x.data());
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(j.cols());
  int used = 0;
  for (int r = 1; r <= replicates; ++r) {
    const std::vector<Statistic> v = model.Replicate(x.data(), r);
    Eigen::VectorXd d(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      const std::size_t t = static_cast<std::size_t>(i);
      d(i) = (v[t].value - base[t].value) / sigma[t];
    }
    if (!d.allFinite()) continue;  // a replicate with no sample of a target
    sum += svd.solve(d).array().square().matrix();
    ++used;
  }
  out->noise_replicates = used;
  if (used == 0) return;
  for (std::size_t c = 0; c < keep.size(); ++c)
    (*fitted)[static_cast<std::size_t>(keep[c])].mc_sd =
        std::sqrt(sum(static_cast<Eigen::Index>(c)) / used);
}

// Each parameter's estimate with its standard error, Wald interval and, for a
// golden_section stage, its profile interval.
void AddFittedParameters(const scene::Scene& scene, const StageSpec& stage,
                         const std::vector<double>& x,
                         const std::vector<FittedParameter>& identification,
                         const std::optional<ProfileInterval>& profile,
                         CalibrationResult* out) {
  const int p = static_cast<int>(stage.parameters.size());
  for (int i = 0; i < p; ++i) {
    FittedParameter f;
    if (!identification.empty()) f = identification[static_cast<std::size_t>(i)];
    f.name = stage.parameters[static_cast<std::size_t>(i)].name;
    f.start = stage.parameters[static_cast<std::size_t>(i)].start;
    scene::Parameters before = scene.params;  // the table's accessor takes a mutable set
    f.scene_value = scene::FindParam(f.name)->real(before);
    f.estimate = x[static_cast<std::size_t>(i)];
    if (profile) {
      f.has_profile = true;
      f.profile = {profile->lower, profile->upper};
      f.profile_open_lower = profile->open_lower;
      f.profile_open_upper = profile->open_upper;
    }
    if (f.has_profile && f.profile_open_lower && f.profile_open_upper) {
      f.identified = false;
      f.not_identified_why =
          "its 95 % profile interval is open at both bounds: the targets do not "
          "bound it within them";
    }
    // No interval for what the targets do not determine.
    const double variance = out->covariance(i, i);
    f.standard_error =
        f.identified && out->covariance_ok && std::isfinite(variance) && variance > 0
            ? std::sqrt(variance)
            : std::nan("");
    f.ci = {f.estimate - kZ95 * f.standard_error, f.estimate + kZ95 * f.standard_error};
    out->parameters.push_back(f);
  }
}

// For each parameter whose start an override file gave: how far the fit
// moved it, against the solver's tolerance.
void AddFixedPoints(const CalibrationSpec& spec, const StageSpec& stage,
                    const std::vector<double>& x, CalibrationResult* out) {
  double norm = 0;
  for (double v : x) norm += v * v;
  const std::size_t first = out->parameters.size() - stage.parameters.size();
  for (std::size_t i = 0; i < stage.parameters.size(); ++i) {
    FittedParameter& f = out->parameters[first + i];
    f.start_from = stage.parameters[i].start_from;
    if (f.start_from.empty()) continue;
    f.fixed_point_change = std::abs(f.estimate - f.start);
    const double se = std::isfinite(f.standard_error) ? f.standard_error : 0.0;
    f.fixed_point_tolerance =
        stage.solver == "golden_section"
            ? spec.tolerance * std::abs(f.estimate)
            : std::max(kLevenbergMarquardtParameterTolerance * std::sqrt(norm),
                       kFixedPointStandardErrors * se);
  }
}

// Each target at the start and at the fit, with its whitened residual there.
void AddFittedTargets(const std::vector<Target>& targets,
                      const std::vector<Statistic>& at_start,
                      const std::vector<Statistic>& fitted,
                      const std::vector<double>& sigma, CalibrationResult* out) {
  for (std::size_t k = 0; k < targets.size(); ++k) {
    FittedTarget t;
    t.target = targets[k];
    t.start = at_start[k];
    t.fitted = fitted[k];
    t.residual = (fitted[k].value - targets[k].lab.value) / sigma[k];
    out->targets.push_back(t);
  }
}

// The stage's start, an InputError naming the experiment file where it lies
// outside the valid region.
std::vector<double> ValidStart(const VirtualModel& model, const StageSpec& stage,
                               const std::string& experiment_file) {
  std::vector<double> x;
  for (const ParameterSpec& s : stage.parameters) x.push_back(s.start);
  const std::string invalid = model.Violation(x.data());
  if (!invalid.empty())
    throw InputError(
        experiment_file,
        stage.pointer.empty() ? "/parameters" : stage.pointer + "/parameters",
        VectorText(stage.parameters, x.data()),
        "the start must lie where the model is defined: " + invalid);
  return x;
}

// A target read from the lab's tracks is measured with the scene's curves f,
// r and g (Figs. 3-5): a stage that fits one of them would move the lab's
// side with the virtual one, and its residual would measure nothing. An
// InputError naming the parameter.
void RefuseCurvesAgainstTracks(const StageSpec& stage, const std::vector<Target>& targets,
                               const std::string& experiment_file) {
  const auto track = std::find_if(targets.begin(), targets.end(),
                                  [](const Target& t) { return t.from_tracks; });
  if (track == targets.end()) return;
  for (const ParameterSpec& p : stage.parameters) {
    const std::string group = p.name.substr(0, p.name.find('/'));
    if (group == "sight" || group == "reach" || group == "glance")
      throw InputError(
          experiment_file, p.pointer + "/name", p.name,
          fmt::format("target {} is read from the lab's sensor tracks with the "
                      "scene's {} curve: fitting the curve would move the lab's "
                      "value with the virtual one; fit it to targets of their own "
                      "stage, or to what the lab reports",
                      track->label, group));
  }
}

// The profile interval of a golden_section stage at its estimate, on the
// last round's weights (those of its search and covariance).
ProfileInterval GoldenSectionProfile(VirtualModel& model,
                                     const std::vector<Target>& targets,
                                     const std::vector<double>& sigma,
                                     const CalibrationSpec& spec, const StageSpec& stage,
                                     double estimate, const std::string& prefix,
                                     const CalibrationProgress& progress,
                                     CalibrationResult* out) {
  const ParameterSpec& ps = stage.parameters[0];
  const ProfileInterval profile = ProfileBounds(
      [&](double v) { return Cost(model, targets, sigma, spec, &v); }, ps.lower, ps.upper,
      estimate, out->final_cost, kProfileRise, spec.relative_step, spec.tolerance);
  out->search_log += profile.log;
  if (progress)
    progress(fmt::format("{}: profile interval [{:.6g}, {:.6g}] ({} evaluations)", prefix,
                         profile.lower, profile.upper, profile.evaluations));
  return profile;
}

}  // namespace

CalibrationResult CalibrateStage(const scene::Scene& scene, const data::LabDataset& lab,
                                 const CalibrationSpec& spec, const StageSpec& stage,
                                 const std::string& experiment_file, std::uint64_t seed,
                                 int trials, const experiment::RunnerOptions& options,
                                 const CalibrationProgress& progress) {
  const auto started = std::chrono::steady_clock::now();
  const std::vector<Target> targets =
      LabTargets(scene, lab, stage.targets, experiment_file);
  RefuseCurvesAgainstTracks(stage, targets, experiment_file);
  const int p = static_cast<int>(stage.parameters.size());
  const int m = static_cast<int>(targets.size());
  VAHF_CHECK(p >= 1 && m >= 1, "a calibration fits at least one parameter to one target");
  VAHF_CHECK(stage.solver != "golden_section" || p == 1,
             "the golden_section solver fits one parameter");
  VirtualModel model(scene, lab, spec, stage, targets, seed, trials, options, progress);
  const std::string prefix =
      stage.name.empty() ? "calibrate" : "calibrate (" + stage.name + ")";

  std::vector<double> x = ValidStart(model, stage, experiment_file);
  const std::vector<Statistic> at_start = model.At(x.data());

  CalibrationResult out;
  out.stage = stage.name;
  out.solver = stage.solver;
  std::vector<double> sigma =
      Weights(targets, at_start, VectorText(stage.parameters, x.data()));
  std::optional<std::array<double, 3>> bracket;
  std::vector<FittedParameter> identification;
  const auto differences = std::make_shared<DifferenceCounts>();
  for (int round = 1; round <= kMaxRounds; ++round) {
    out.rounds = round;
    ceres::Problem problem;
    BuildProblem(&problem, &model, spec, stage, targets, sigma, differences, x.data());
    const std::string brief = stage.solver == "golden_section"
                                  ? GoldenSectionRound(model, targets, sigma, spec, stage,
                                                       round, &x, &bracket, &out)
                                  : LevenbergMarquardtRound(spec, &problem, &out);
    out.ceres_brief += fmt::format("round {}: {}\n", round, brief);
    if (progress)
      progress(fmt::format("{}: round {}: {} ({})", prefix, round,
                           VectorText(stage.parameters, x.data()), brief));

    const std::vector<Statistic>& at_fit = model.At(x.data());
    const std::vector<double> refit =
        Weights(targets, at_fit, VectorText(stage.parameters, x.data()));
    if (!WeightsSettled(refit, sigma) && round < kMaxRounds) {
      sigma = refit;
      continue;
    }
    // The covariance of this round's problem, at the estimate; which
    // parameters its targets determine.
    if (stage.solver == "golden_section") {
      EstimateCovariance(&problem, x, p, &out);
      out.rank = RankOf(JacobianOf(&problem, m, p),
                        Eigen::VectorXd::Constant(1, x[0] != 0 ? std::abs(x[0]) : 1.0));
    } else {
      identification = Identify(model, &problem, targets, sigma, spec, stage, x, &out);
      MonteCarloSpread(model, sigma, x, spec.noise_replicates, &out, &identification);
      if (spec.intervals == "profile")
        ProfileIntervals(model, spec, stage, targets, sigma, x, prefix, progress, &out,
                         &identification);
    }
    break;
  }

  std::optional<ProfileInterval> profile;
  if (stage.solver == "golden_section")
    profile = GoldenSectionProfile(model, targets, sigma, spec, stage, x[0], prefix,
                                   progress, &out);
  AddFittedParameters(scene, stage, x, identification, profile, &out);
  AddFixedPoints(spec, stage, x, &out);
  out.correlation = Correlation(out.covariance);
  out.differences = *differences;
  out.refused = model.refused();
  AddFittedTargets(targets, at_start, model.At(x.data()), sigma, &out);
  out.evaluations = model.evaluations();
  out.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return out;
}

scene::Scene WithEstimates(const scene::Scene& scene,
                           const std::vector<CalibrationResult>& stages) {
  scene::Scene out = scene;
  for (const CalibrationResult& r : stages)
    for (const FittedParameter& f : r.parameters)
      scene::FindParam(f.name)->real(out.params) = f.estimate;
  return out;
}

std::vector<CalibrationResult> Calibrate(
    const scene::Scene& scene, const data::LabDataset& lab, const CalibrationSpec& spec,
    const std::string& experiment_file, std::uint64_t seed, int trials,
    const experiment::RunnerOptions& options, const CalibrationProgress& progress) {
  std::vector<CalibrationResult> out;
  for (const StageSpec& stage : spec.stages)
    out.push_back(CalibrateStage(WithEstimates(scene, out), lab, spec, stage,
                                 experiment_file, seed, trials, options, progress));
  return out;
}

}  // namespace vahf::calibrate
