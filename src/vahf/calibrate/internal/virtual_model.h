// The virtual side of a calibration stage (calibration.h): the statistics
// of every target at a parameter vector, simulated once each, and the cost
// the stage's solvers minimise over them. Internal to calibrate/.
#pragma once
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "vahf/calibrate/calibration.h"
#include "vahf/core/error.h"
#include "vahf/experiment/design.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"

namespace ceres {
class LossFunction;
}  // namespace ceres

namespace vahf::calibrate {

// Sets each of `params` to its value in x in `scene`.
void SetParameters(const std::vector<ParameterSpec>& params, const double* x,
                   scene::Scene* scene);

// "name value, name value" of the parameters at x, for progress and errors.
std::string VectorText(const std::vector<ParameterSpec>& params, const double* x);

// The virtual statistics of every target at a parameter vector, each vector
// simulated once: Ceres asks for the same point again (a Jacobian at an
// accepted step, the covariance at the estimate).
class VirtualModel {
 public:
  VirtualModel(const scene::Scene& scene, const data::LabDataset& lab,
               const CalibrationSpec& spec, const StageSpec& stage,
               const std::vector<Target>& targets, std::uint64_t seed, int trials,
               const experiment::RunnerOptions& options,
               const CalibrationProgress& progress)
      : scene_(scene),
        lab_(lab),
        spec_(spec),
        stage_(stage),
        targets_(targets),
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
    // eta and lambda_c are read off the decision trace.
    for (const Target& t : targets_) {
      trace_ = trace_ || scene::AtInstant(t.spec.quantity);
      operators_ = operators_ || t.spec.segment == 0;
    }
  }

  // Empty when x lies in the valid region: within the parameters' bounds,
  // a scene whose rules hold (scene::ParameterViolation) and, for a design
  // of the lab's operators, the reach rule D1 < D2 < D3 for each of them;
  // else the first rule broken.
  std::string Violation(const double* x) const {
    for (std::size_t i = 0; i < stage_.parameters.size(); ++i) {
      const ParameterSpec& p = stage_.parameters[i];
      if (!(x[i] >= p.lower && x[i] <= p.upper))
        return fmt::format("{} = {:.6g} lies outside its bounds [{:.6g}, {:.6g}]", p.name,
                           x[i], p.lower, p.upper);
    }
    const scene::Scene s = Applied(x);
    std::string violation = scene::ParameterViolation(s);
    if (violation.empty() && operators_) violation = LabReachViolation(s, lab_);
    return violation;
  }

  // The virtual statistics at x; NaN (no value: the solver steps back)
  // outside the valid region, where nothing is simulated.
  const std::vector<Statistic>& At(const double* x) {
    std::vector<double> key(x, x + stage_.parameters.size());
    auto found = cache_.find(key);
    if (found != cache_.end()) return found->second;
    const std::string violation = Violation(x);
    if (!violation.empty()) {
      ++refused_;
      if (progress_)
        progress_(fmt::format("calibrate: {} refused ({}); the solver steps back",
                              VectorText(stage_.parameters, x), violation));
      Statistic none;
      none.value = std::nan("");
      return cache_.emplace(std::move(key), std::vector<Statistic>(targets_.size(), none))
          .first->second;
    }
    const auto start = std::chrono::steady_clock::now();
    const scene::Scene s = Applied(x);
    std::vector<Statistic> stats(targets_.size());
    std::uint64_t cycles = 0;  // the stream indices the lab's design used
    if (operators_) {
      const experiment::DesignRun run = RunOperators(s, 0, &cycles);
      for (std::size_t i = 0; i < targets_.size(); ++i)
        if (targets_[i].spec.segment == 0) stats[i] = VirtualStatistic(targets_[i], run);
    }
    if (!segments_.empty()) {
      // The scene's operator works the hour; only the segments the targets
      // name are run (the pilot, which measures the work rate, always is),
      // beside the lab's design on stream indices of their own, so that the
      // two kinds of target are independent residuals.
      const experiment::FatigueRun f =
          experiment::RunFatigue(std::make_shared<const scene::Scene>(s), spec_.fatigue,
                                 trials_, seed_, options_, options_, segments_, cycles);
      for (std::size_t i = 0; i < targets_.size(); ++i)
        if (targets_[i].spec.segment > 0)
          stats[i] = VirtualStatistic(targets_[i], f.run, f.segments);
    }
    PoolVariances(targets_, &stats);
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
  int refused() const { return refused_; }
  // Whether the design is the lab's operators (not the hour of work).
  bool lab_design() const { return segments_.empty(); }

  // The statistics at x (valid, of a lab design) on other virtual people:
  // replicate r >= 1 draws from the cycles r x (operators x trials) on, none
  // of which the fit used. Not cached.
  std::vector<Statistic> Replicate(const double* x, int r) {
    VAHF_CHECK(lab_design() && r >= 1 && Violation(x).empty(),
               "a replicate of a valid point of a lab design");
    const experiment::DesignRun run = RunOperators(Applied(x), r, nullptr);
    std::vector<Statistic> stats;
    for (const Target& t : targets_) stats.push_back(VirtualStatistic(t, run));
    PoolVariances(targets_, &stats);
    ++evaluations_;
    return stats;
  }

 private:
  scene::Scene Applied(const double* x) const {
    scene::Scene out = scene_;
    SetParameters(stage_.parameters, x, &out);
    return out;
  }

  // The design of the lab's operators on scene `s`, replicate r (0: the
  // fit's own) drawing from the cycles r x (operators x trials) on; *cycles,
  // if given, is set to the number of stream indices one replicate takes.
  experiment::DesignRun RunOperators(const scene::Scene& s, int r,
                                     std::uint64_t* cycles) {
    std::vector<experiment::Condition> conditions = LabConditions(s, lab_, trials_);
    const std::uint64_t span = conditions.size() * static_cast<std::uint64_t>(trials_);
    for (experiment::Condition& c : conditions)
      c.cycle_offset += static_cast<std::uint64_t>(r) * span;
    if (cycles) *cycles = span;
    return experiment::RunDesign(conditions, trials_, seed_, trace_, options_);
  }

  const scene::Scene& scene_;
  const data::LabDataset& lab_;
  const CalibrationSpec& spec_;
  const StageSpec& stage_;
  const std::vector<Target>& targets_;
  std::uint64_t seed_;
  int trials_;
  experiment::RunnerOptions options_;
  CalibrationProgress progress_;
  std::map<std::vector<double>, std::vector<Statistic>> cache_;
  std::vector<int>
      segments_;            // 0-based segments the targets read; empty: no fatigue design
  bool trace_ = false;      // a target reads the decision trace (eta, lambda_c)
  bool operators_ = false;  // a target reads the design of the lab's operators
  int evaluations_ = 0;
  int refused_ = 0;  // points outside the valid region asked for
};

// The stage's robust loss (its `loss`), nullptr for plain least squares.
ceres::LossFunction* MakeLoss(const CalibrationSpec& spec);

// The cost Ceres minimises, 1/2 sum rho(r_i^2), at the stage's one-parameter
// vector x (the golden_section solver minimises the same).
double Cost(VirtualModel& model, const std::vector<Target>& targets,
            const std::vector<double>& sigma, const CalibrationSpec& spec,
            const double* x);

}  // namespace vahf::calibrate
