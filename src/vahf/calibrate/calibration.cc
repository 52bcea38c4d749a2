#include "vahf/calibrate/calibration.h"

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include "vahf/calibrate/bracketed_search.h"
#include "vahf/core/error.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::calibrate {
namespace {

// Two-sided 95 % normal quantile, for intervals from the covariance.
constexpr double kZ95 = 1.959963984540054;
// chi^2 with one degree of freedom at 0.95 (3.841459, gsl_cdf_chisq_Pinv),
// halved: the rise of a cost of 1/2 sum r^2 that bounds the 95 % profile
// interval.
const double kProfileRise = 0.5 * gsl_cdf_chisq_Pinv(0.95, 1.0);

std::string VectorText(const std::vector<ParameterSpec>& params, const double* x) {
  std::string out;
  for (std::size_t i = 0; i < params.size(); ++i)
    out += fmt::format("{}{} {:.6g}", i ? ", " : "", params[i].name, x[i]);
  return out;
}

// The virtual statistics of every target at a parameter vector, each vector
// simulated once: Ceres asks for the same point again (a Jacobian at an
// accepted step, the covariance at the estimate).
class VirtualModel {
 public:
  VirtualModel(const scene::Scene& scene, const data::LabDataset& lab,
               const CalibrationSpec& spec, const StageSpec& stage,
               const std::vector<Target>& targets, const std::string& experiment_file,
               std::uint64_t seed, int trials, const experiment::RunnerOptions& options,
               const CalibrationProgress& progress)
      : scene_(scene),
        lab_(lab),
        spec_(spec),
        stage_(stage),
        targets_(targets),
        file_(experiment_file),
        seed_(seed),
        trials_(trials),
        options_(options),
        progress_(progress) {
    options_.progress = false;  // one line per evaluation instead (progress_)
    for (const Target& t : targets_)
      if (t.spec.segment > 0 && std::find(segments_.begin(), segments_.end(),
                                          t.spec.segment - 1) == segments_.end())
        segments_.push_back(t.spec.segment - 1);
    std::sort(segments_.begin(), segments_.end());
  }

  const std::vector<Statistic>& At(const double* x) {
    std::vector<double> key(x, x + stage_.parameters.size());
    auto found = cache_.find(key);
    if (found != cache_.end()) return found->second;
    const auto start = std::chrono::steady_clock::now();
    const scene::Scene s = WithParameters(scene_, stage_.parameters, key, file_);
    std::vector<Statistic> stats;
    if (segments_.empty()) {
      const experiment::DesignRun run = experiment::RunDesign(
          LabConditions(s, lab_, trials_), trials_, seed_, false, options_);
      for (const Target& t : targets_) stats.push_back(VirtualStatistic(t, run));
    } else {
      // The scene's operator works the hour; only the segments the targets
      // name are run (the pilot, which measures the work rate, always is).
      const experiment::FatigueRun f =
          experiment::RunFatigue(std::make_shared<const scene::Scene>(s), spec_.fatigue,
                                 trials_, seed_, options_, options_, segments_);
      for (const Target& t : targets_)
        stats.push_back(VirtualStatistic(t, f.run, f.segments));
    }
    ++evaluations_;
    if (progress_)
      progress_(fmt::format(
          "calibrate: evaluation {} at {} ({:.1f} s)", evaluations_,
          VectorText(stage_.parameters, x),
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
              .count()));
    return cache_.emplace(std::move(key), std::move(stats)).first->second;
  }

  int evaluations() const { return evaluations_; }

 private:
  const scene::Scene& scene_;
  const data::LabDataset& lab_;
  const CalibrationSpec& spec_;
  const StageSpec& stage_;
  const std::vector<Target>& targets_;
  std::string file_;
  std::uint64_t seed_;
  int trials_;
  experiment::RunnerOptions options_;
  CalibrationProgress progress_;
  std::map<std::vector<double>, std::vector<Statistic>> cache_;
  std::vector<int>
      segments_;  // 0-based segments the targets read; empty: no fatigue design
  int evaluations_ = 0;
};

// One target's whitened residual at a fixed weight, for Ceres' numeric
// differentiation. Each target is its own residual block, so that the robust
// loss weighs each target by its own residual, not by the norm of all.
struct Residual {
  VirtualModel* model;
  const Target* target;
  std::size_t index;
  double sigma;
  bool operator()(double const* const* parameters, double* residual) const {
    const Statistic& v = model->At(parameters[0])[index];
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

ceres::LossFunction* MakeLoss(const CalibrationSpec& spec) {
  if (spec.loss == "huber") return new ceres::HuberLoss(spec.loss_scale);
  if (spec.loss == "cauchy") return new ceres::CauchyLoss(spec.loss_scale);
  return nullptr;  // "none": plain least squares
}

}  // namespace

scene::Scene WithParameters(const scene::Scene& scene,
                            const std::vector<ParameterSpec>& params,
                            const std::vector<double>& values,
                            const std::string& experiment_file) {
  VAHF_CHECK(params.size() == values.size(), "one value per fitted parameter");
  scene::Scene out = scene;
  for (std::size_t i = 0; i < params.size(); ++i) {
    const scene::ParamSpec* spec = scene::FindParam(params[i].name);
    VAHF_CHECK(spec && spec->real, "fitted parameters are real-valued table entries");
    spec->real(out.params) = values[i];
  }
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

// The cost Ceres minimises, 1/2 sum rho(r_i^2), at the stage's one-parameter
// vector x (the golden_section solver minimises the same).
double Cost(VirtualModel& model, const std::vector<Target>& targets,
            const std::vector<double>& sigma, const CalibrationSpec& spec, double x) {
  const std::vector<Statistic>& v = model.At(&x);
  const std::unique_ptr<ceres::LossFunction> loss(MakeLoss(spec));
  double cost = 0;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    if (!std::isfinite(v[i].value)) return std::nan("");  // no sample
    const double r = (v[i].value - targets[i].lab.value) / sigma[i];
    double rho[3] = {r * r, 1, 0};
    if (loss) loss->Evaluate(r * r, rho);
    cost += 0.5 * rho[0];
  }
  return cost;
}

// The stage's problem at `x`: one residual block per target, bounds.
void BuildProblem(ceres::Problem* problem, VirtualModel* model,
                  const CalibrationSpec& spec, const StageSpec& stage,
                  const std::vector<Target>& targets, const std::vector<double>& sigma,
                  double* x) {
  ceres::NumericDiffOptions diff;
  diff.relative_step_size = spec.relative_step;
  const int p = static_cast<int>(stage.parameters.size());
  for (std::size_t i = 0; i < targets.size(); ++i) {
    auto* cost = new ceres::DynamicNumericDiffCostFunction<Residual, ceres::CENTRAL>(
        new Residual{model, &targets[i], i, sigma[i]}, ceres::TAKE_OWNERSHIP, diff);
    cost->AddParameterBlock(p);
    cost->SetNumResiduals(1);
    problem->AddResidualBlock(cost, MakeLoss(spec), x);
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
      [&](double v) { return Cost(model, targets, sigma, spec, v); }, ps.lower, ps.upper,
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
  solver.parameter_tolerance = 1e-4;
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

// Each parameter's estimate with its standard error, Wald interval and, for a
// golden_section stage, its profile interval.
void AddFittedParameters(const scene::Scene& scene, const StageSpec& stage,
                         const std::vector<double>& x,
                         const std::optional<ProfileInterval>& profile,
                         CalibrationResult* out) {
  const int p = static_cast<int>(stage.parameters.size());
  for (int i = 0; i < p; ++i) {
    FittedParameter f;
    f.name = stage.parameters[static_cast<std::size_t>(i)].name;
    f.start = stage.parameters[static_cast<std::size_t>(i)].start;
    scene::Parameters before = scene.params;  // the table's accessor takes a mutable set
    f.scene_value = scene::FindParam(f.name)->real(before);
    f.estimate = x[static_cast<std::size_t>(i)];
    f.standard_error =
        out->covariance_ok ? std::sqrt(out->covariance(i, i)) : std::nan("");
    f.ci = {f.estimate - kZ95 * f.standard_error, f.estimate + kZ95 * f.standard_error};
    if (profile) {
      f.has_profile = true;
      f.profile = {profile->lower, profile->upper};
      f.profile_open_lower = profile->open_lower;
      f.profile_open_upper = profile->open_upper;
    }
    out->parameters.push_back(f);
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

}  // namespace

CalibrationResult CalibrateStage(const scene::Scene& scene, const data::LabDataset& lab,
                                 const CalibrationSpec& spec, const StageSpec& stage,
                                 const std::string& experiment_file, std::uint64_t seed,
                                 int trials, const experiment::RunnerOptions& options,
                                 const CalibrationProgress& progress) {
  const auto started = std::chrono::steady_clock::now();
  const std::vector<Target> targets = LabTargets(lab, stage.targets, experiment_file);
  const int p = static_cast<int>(stage.parameters.size());
  const int m = static_cast<int>(targets.size());
  VAHF_CHECK(p >= 1 && m >= 1, "a calibration fits at least one parameter to one target");
  VAHF_CHECK(stage.solver != "golden_section" || p == 1,
             "the golden_section solver fits one parameter");
  VirtualModel model(scene, lab, spec, stage, targets, experiment_file, seed, trials,
                     options, progress);
  const std::string prefix =
      stage.name.empty() ? "calibrate" : "calibrate (" + stage.name + ")";

  std::vector<double> x;
  for (const ParameterSpec& s : stage.parameters) x.push_back(s.start);
  const std::vector<Statistic> at_start = model.At(x.data());

  CalibrationResult out;
  out.stage = stage.name;
  out.solver = stage.solver;
  std::vector<double> sigma =
      Weights(targets, at_start, VectorText(stage.parameters, x.data()));
  std::optional<std::array<double, 3>> bracket;
  for (int round = 1; round <= kMaxRounds; ++round) {
    out.rounds = round;
    ceres::Problem problem;
    BuildProblem(&problem, &model, spec, stage, targets, sigma, x.data());
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
    bool stable = true;
    for (int i = 0; i < m; ++i)
      stable = stable && std::abs(refit[i] / sigma[i] - 1) < 0.1;
    if (!stable && round < kMaxRounds) {
      sigma = refit;
      continue;
    }
    // The covariance of this round's problem, at the estimate.
    EstimateCovariance(&problem, x, p, &out);
    break;
  }

  // The profile interval of a golden_section stage, on the last round's
  // weights (those of its search and covariance).
  std::optional<ProfileInterval> profile;
  if (stage.solver == "golden_section") {
    const ParameterSpec& ps = stage.parameters[0];
    profile = ProfileBounds(
        [&](double v) { return Cost(model, targets, sigma, spec, v); }, ps.lower,
        ps.upper, x[0], out.final_cost, kProfileRise, spec.relative_step, spec.tolerance);
    out.search_log += profile->log;
    if (progress)
      progress(fmt::format("{}: profile interval [{:.6g}, {:.6g}] ({} evaluations)",
                           prefix, profile->lower, profile->upper, profile->evaluations));
  }
  AddFittedParameters(scene, stage, x, profile, &out);
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
