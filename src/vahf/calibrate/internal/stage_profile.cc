#include "vahf/calibrate/internal/stage_profile.h"

#include <fmt/format.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "vahf/calibrate/profile_likelihood.h"

namespace vahf::calibrate {
namespace {

const double kProfileRise = ProfileRise();

// Calls of the profile per end of an interval, each a re-fit of the other
// parameters: the secant on the signed root reaches a quadratic profile's
// end in one call and a curved one's in two to four (profile_likelihood.h).
// With 6, 2 of the 200 intervals of the 50 coverage datasets kept an end
// not reached (d1 of dataset 46 and one of kappa's); with 8 both end.
constexpr int kProfileCalls = 8;

// Design evaluations per profile value (SecantLeastSquares), after the
// forward differences of its Jacobian, and the fall of the cost below which
// its re-fit stops: far below the rise of 1.92 it measures.
constexpr int kRefitEvaluations = 10;
constexpr double kRefitTolerance = 0.005;
// Re-fits, each from where the last ended with its Jacobian differenced
// anew, of a profile value the first leaves at or beyond the target: a
// re-fit stops on its evaluations, not on a minimum, and a cost it has
// not brought down would close the interval inside the true end. Measured
// on coverage dataset 39 (d2's profile): one re-fit gave rises of 2.06,
// 6.17 and 2.88 at d2 = 0.350, 0.366 and 0.374, where Levenberg-Marquardt
// with d2 held gave 0.57, 0.78 and 1.13 at d2 = 0.35, 0.37 and 0.39.
constexpr int kRefitRounds = 4;

// The profile's value with *at's held parameters where they are: the least
// cost over the parameters `free`, re-fitted from *at (a valid point) by
// secant steps on `jacobian` (the whitened residuals' derivatives in those
// parameters, kept current); *at moves to the re-fit.
double Refit(VirtualModel& model, const CalibrationSpec& spec, const StageSpec& stage,
             const std::vector<Target>& targets, const std::vector<double>& sigma,
             const std::vector<std::size_t>& free, Eigen::MatrixXd* jacobian,
             std::vector<double>* at) {
  const auto q = static_cast<Eigen::Index>(free.size());
  if (q > 0) {
    Eigen::VectorXd y(q), lower(q), upper(q);
    for (Eigen::Index k = 0; k < q; ++k) {
      const std::size_t j = free[static_cast<std::size_t>(k)];
      y(k) = (*at)[j];
      lower(k) = stage.parameters[j].lower;
      upper(k) = stage.parameters[j].upper;
    }
    std::vector<double> x = *at;
    const auto residuals = [&](const Eigen::VectorXd& v, Eigen::VectorXd* r) {
      for (Eigen::Index k = 0; k < q; ++k) x[free[static_cast<std::size_t>(k)]] = v(k);
      if (!model.Violation(x.data()).empty()) return false;
      const std::vector<Statistic>& stats = model.At(x.data());
      r->resize(static_cast<Eigen::Index>(targets.size()));
      for (std::size_t t = 0; t < targets.size(); ++t)
        (*r)(static_cast<Eigen::Index>(t)) =
            (stats[t].value - targets[t].lab.value) / sigma[t];
      return r->allFinite();
    };
    // The Jacobian differenced anew at each profile value: the
    // reach curve bends the valley, so that d1's slope at the estimate is not
    // its slope where kappa's profile goes, and Broyden's updates from steps
    // shorter than the difference step measure the common random numbers'
    // roughness, not the slope. Measured on coverage datasets 3 and 6, whose
    // kappa profiles ended at 294.5 and 297.4 with Broyden's updates alone:
    // full Levenberg-Marquardt re-fits with kappa held at 300 rose only 1.26
    // and 0.82 above the estimate's cost.
    Eigen::VectorXd r0;
    if (residuals(y, &r0))
      DifferenceColumns(residuals, y, r0, lower, upper, spec.relative_step, jacobian);
    const SecantFit fit = SecantLeastSquares(residuals, y, jacobian, lower, upper,
                                             kRefitEvaluations, kRefitTolerance);
    for (Eigen::Index k = 0; k < q; ++k)
      (*at)[free[static_cast<std::size_t>(k)]] = fit.y(k);
  }
  return Cost(model, targets, sigma, spec, at->data());
}

// A valid point with parameter i at v to re-fit from: the first of
// `guesses` that is valid with i set to v, else the first with one of the
// re-fitted parameters `free` moved part of the way to one of its bounds (a
// rule such as D1 < D2 < D3 may admit i's value only with another moved);
// none when neither is.
std::optional<std::vector<double>> StartAt(const VirtualModel& model,
                                           const StageSpec& stage,
                                           const std::vector<std::size_t>& free,
                                           std::size_t i, double v,
                                           std::vector<std::vector<double>> guesses) {
  for (std::vector<double>& g : guesses) {
    g[i] = v;
    if (model.Violation(g.data()).empty()) return g;
  }
  for (const std::vector<double>& g : guesses)
    for (std::size_t j : free)
      for (double bound : {stage.parameters[j].lower, stage.parameters[j].upper})
        for (double part : {0.125, 0.25, 0.5, 1.0}) {
          std::vector<double> h = g;
          h[j] += part * (bound - g[j]);
          if (model.Violation(h.data()).empty()) return h;
        }
  return std::nullopt;
}

// How far parameter i's profile may go from the estimate x toward `bound`:
// the bound, or the last value (bisected) at which StartAt finds a valid
// point. With the others re-fitted this may lie beyond EdgeToward's, which
// holds them.
double ProfileEdge(const VirtualModel& model, const StageSpec& stage,
                   const std::vector<std::size_t>& free, const std::vector<double>& x,
                   std::size_t i, double bound) {
  const auto valid_at = [&](double v) {
    return StartAt(model, stage, free, i, v, {x}).has_value();
  };
  if (valid_at(bound)) return bound;
  double valid = x[i], invalid = bound;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (valid + invalid);
    if (mid == valid || mid == invalid) break;
    (valid_at(mid) ? valid : invalid) = mid;
  }
  return valid;
}

// The profile of one identified parameter i of a Levenberg-Marquardt stage
// at its estimate x, on the weights `sigma` of its covariance: each profile
// value re-fits the other identified parameters (Refit), the unidentified
// held.
class ParameterProfile {
 public:
  ParameterProfile(VirtualModel& model, const CalibrationSpec& spec,
                   const StageSpec& stage, const std::vector<Target>& targets,
                   const std::vector<double>& sigma, const std::vector<double>& x,
                   const CalibrationResult& fit, std::vector<std::size_t> identified,
                   std::size_t i)
      : model_(model),
        spec_(spec),
        stage_(stage),
        targets_(targets),
        sigma_(sigma),
        x_(x),
        covariance_(fit.covariance),
        i_(i),
        at_estimate_(Cost(model, targets, sigma, spec, x.data())) {
    for (std::size_t j : identified)
      if (j != i) free_.push_back(j);
    // The whitened Jacobian's columns of the re-fitted parameters at the
    // estimate: each side's secant steps start from it and update it.
    columns_.resize(fit.jacobian.rows(), static_cast<Eigen::Index>(free_.size()));
    for (std::size_t k = 0; k < free_.size(); ++k)
      columns_.col(static_cast<Eigen::Index>(k)) =
          fit.jacobian.col(static_cast<Eigen::Index>(free_[k]));
    if (!columns_.allFinite()) free_.clear();  // no slope to re-fit on: the scan
  }

  // The end of the 95 % profile interval toward `bound` (the parameter's),
  // searched from the Wald end (ProfileEndToward).
  ProfileEnd End(double bound) {
    const double edge = ProfileEdge(model_, stage_, free_, x_, i_, bound);
    inside_ = x_;
    inside_jacobian_ = columns_;
    const double var = Variance();
    const double se = var > 0 ? std::sqrt(var) : 0.5 * std::abs(edge - x_[i_]);
    const double first = x_[i_] + (edge > x_[i_] ? 1 : -1) * kZ95 * se;
    return ProfileEndToward([this](double v) { return Rise(v); }, x_[i_], edge, first,
                            kProfileRise, kProfileCalls);
  }

  // The least rise a re-fit found (below 0: a cost under the estimate's).
  double least_rise() const { return least_rise_; }

 private:
  double Variance() const {
    const auto ii = static_cast<Eigen::Index>(i_);
    const double var = covariance_(ii, ii);
    return std::isfinite(var) && var > 0 ? var : 0;
  }

  // `from` moved along the linearised valley (the covariance's regression
  // of the others on parameter i) to parameter i at v.
  std::vector<double> Valley(std::vector<double> from, double v) const {
    const double var = Variance();
    for (std::size_t j : free_) {
      const double slope = var > 0 ? covariance_(static_cast<Eigen::Index>(j),
                                                 static_cast<Eigen::Index>(i_)) /
                                         var
                                   : 0;
      if (std::isfinite(slope)) from[j] += slope * (v - from[i_]);
    }
    return from;
  }

  // The profile's rise at v. The re-fit starts from the lower-cost of the
  // valley's guesses from the last re-fit inside the interval and from the
  // estimate; a re-fit beyond the interval may have ended far from the
  // valley, and is not carried on.
  double Rise(double v) {
    std::optional<std::vector<double>> start;
    double start_cost = std::numeric_limits<double>::infinity();
    for (const std::vector<double>& guess : {Valley(inside_, v), Valley(x_, v)}) {
      const std::optional<std::vector<double>> g =
          StartAt(model_, stage_, free_, i_, v, {guess, inside_, x_});
      if (!g) continue;
      const double cost = Cost(model_, targets_, sigma_, spec_, g->data());
      if (!start || (std::isfinite(cost) && !(start_cost <= cost))) {
        start = g;
        start_cost = cost;
      }
    }
    if (!start) return std::nan("");
    std::vector<double> at = *start;
    Eigen::MatrixXd jacobian = inside_jacobian_;
    double rise = Refit(model_, spec_, stage_, targets_, sigma_, free_, &jacobian, &at) -
                  at_estimate_;
    for (int round = 1; round < kRefitRounds && rise >= kProfileRise; ++round) {
      const double again =
          Refit(model_, spec_, stage_, targets_, sigma_, free_, &jacobian, &at) -
          at_estimate_;
      const bool moved = again < rise - kRefitTolerance;
      rise = std::min(rise, again);
      if (!moved) break;
    }
    if (rise < kProfileRise) {
      inside_ = at;
      inside_jacobian_ = jacobian;
    }
    least_rise_ = std::min(least_rise_, rise);
    return rise;
  }

  VirtualModel& model_;
  const CalibrationSpec& spec_;
  const StageSpec& stage_;
  const std::vector<Target>& targets_;
  const std::vector<double>& sigma_;
  const std::vector<double>& x_;
  const Eigen::MatrixXd& covariance_;
  std::size_t i_;
  double at_estimate_;
  std::vector<std::size_t> free_;  // the re-fitted parameters
  Eigen::MatrixXd columns_;
  std::vector<double> inside_;       // the last re-fit inside the interval
  Eigen::MatrixXd inside_jacobian_;  // Broyden's Jacobian as of that re-fit
  double least_rise_ = 0;
};

}  // namespace

void ProfileIntervals(VirtualModel& model, const CalibrationSpec& spec,
                      const StageSpec& stage, const std::vector<Target>& targets,
                      const std::vector<double>& sigma, const std::vector<double>& x,
                      const std::string& prefix, const CalibrationProgress& progress,
                      CalibrationResult* out, std::vector<FittedParameter>* fitted) {
  std::vector<std::size_t> identified;
  for (std::size_t i = 0; i < fitted->size(); ++i)
    if ((*fitted)[i].identified) identified.push_back(i);
  for (std::size_t i : identified) {
    ParameterProfile profile(model, spec, stage, targets, sigma, x, *out, identified, i);
    const ProfileEnd lower = profile.End(stage.parameters[i].lower),
                     upper = profile.End(stage.parameters[i].upper);
    out->profile_least_rise = std::min(out->profile_least_rise, profile.least_rise());
    FittedParameter& f = (*fitted)[i];
    f.has_profile = true;
    f.profile = {lower.bound, upper.bound};
    f.profile_open_lower = lower.open;
    f.profile_open_upper = upper.open;
    f.profile_reached = lower.reached && upper.reached;
    f.profile_points = lower.points;
    f.profile_points.insert(f.profile_points.end(), upper.points.begin(),
                            upper.points.end());
    f.profile_points.emplace_back(x[i], 0.0);
    std::sort(f.profile_points.begin(), f.profile_points.end());
    if (progress)
      progress(fmt::format("{}: profile interval of {}: [{:.6g}, {:.6g}]{} ({} re-fits)",
                           prefix, stage.parameters[i].name, f.profile.lower,
                           f.profile.upper,
                           f.profile_reached ? "" : ", an end not reached",
                           lower.points.size() + upper.points.size()));
  }
}

}  // namespace vahf::calibrate
