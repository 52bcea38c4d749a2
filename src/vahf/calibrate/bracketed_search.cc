#include "vahf/calibrate/bracketed_search.h"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <iterator>
#include <map>
#include <memory>

#include "vahf/core/error.h"

namespace vahf::calibrate {
namespace {

// The golden ratio: each step of the walk is this many times the last
// (Numerical Recipes' mnbrak).
constexpr double kGrow = 1.618034;
// Higher than any cost a calibration computes (a sum of squared whitened
// residuals): what a non-finite cost counts as, since GSL refuses one.
constexpr double kNoCost = 1e100;
// Points closer than this fraction of the tolerance are one point.
constexpr double kSame = 1e-3;

// The search variable u: log(x) for a positive range, else x.
struct Scale {
  bool logs;
  double ToU(double x) const { return logs ? std::log(x) : x; }
  double ToX(double u) const { return logs ? std::exp(u) : u; }
};

// Restores GSL's error handler on scope exit: the search reads GSL's status
// codes instead of letting its default handler abort.
struct GslHandlerOff {
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  ~GslHandlerOff() { gsl_set_error_handler(old); }
};

// The cost at points u of the search variable, each evaluated once (each
// evaluation is a whole design), with the lowest cost seen and its bracket.
class SearchPoints {
 public:
  // A point seen and its strictly higher neighbours, if any.
  struct Bracket {
    std::map<double, double>::const_iterator a, m, c;
    bool has_a = false, has_c = false;
  };

  SearchPoints(const std::function<double(double)>& cost, double lower, double upper,
               double start, double tolerance,
               const std::optional<std::array<double, 3>>& hint)
      : scale(Scale{lower > 0}),
        lo(scale.ToU(lower)),
        hi(scale.ToU(upper)),
        u0(scale.ToU(start)),
        cost_(cost),
        lower_(lower),
        upper_(upper),
        tolerance_(tolerance),
        // Points given as x (the start, the bounds, a hint) are evaluated at
        // that x exactly, not at exp(log(x)): the caller's cache knows them by
        // their bits.
        given_({{scale.ToU(start), start}, {lo, lower}, {hi, upper}}) {
    if (hint)
      for (double x : *hint)
        if (lower <= x && x <= upper) given_.emplace(scale.ToU(x), x);
  }

  // The cost at u. GSL's golden section computes each new interior point
  // afresh, so a point it has evaluated comes back some ulps off: a point
  // within kSame of the tolerance from one seen is that point.
  double operator()(double u) {
    u = std::clamp(u, lo, hi);
    const double same =
        kSame * (scale.logs ? std::log1p(tolerance_) : tolerance_ * std::fabs(u));
    auto it = seen_.lower_bound(u - same);
    if (it != seen_.end() && it->first <= u + same) return it->second;
    const auto exact = given_.find(u);
    const double x =
        exact != given_.end() ? exact->second : std::clamp(scale.ToX(u), lower_, upper_);
    double c = cost_(x);
    if (!std::isfinite(c)) c = kNoCost;
    seen_.emplace(u, c);
    return c;
  }

  // The parameter value at u: a given point's exact x.
  double XOf(double u) const {
    const auto exact = given_.find(u);
    return exact != given_.end() ? exact->second
                                 : std::clamp(scale.ToX(u), lower_, upper_);
  }

  // Whether a bracket [a, c] is narrow enough around `u`.
  bool NarrowEnough(double a, double c, double u) const {
    return c - a < (scale.logs ? std::log1p(tolerance_)
                               : tolerance_ * std::max(std::fabs(u), 1e-300));
  }

  // The lowest cost seen (ties: the one nearest the start) and its bracket.
  Bracket Lowest() const {
    Bracket b;
    b.m = seen_.begin();
    for (auto it = seen_.begin(); it != seen_.end(); ++it)
      if (it->second < b.m->second ||
          (it->second == b.m->second &&
           std::fabs(it->first - u0) < std::fabs(b.m->first - u0)))
        b.m = it;
    for (auto it = b.m; it != seen_.begin();) {
      --it;
      if (it->second > b.m->second) {
        b.a = it;
        b.has_a = true;
        break;
      }
    }
    for (auto it = std::next(b.m); it != seen_.end(); ++it)
      if (it->second > b.m->second) {
        b.c = it;
        b.has_c = true;
        break;
      }
    return b;
  }

  // The lowest and highest points seen.
  double Leftmost() const { return seen_.begin()->first; }
  double Rightmost() const { return std::prev(seen_.end())->first; }

  const Scale scale;
  const double lo, hi;  // the bounds in u
  const double u0;      // the start in u

 private:
  const std::function<double(double)>& cost_;
  const double lower_, upper_, tolerance_;
  std::map<double, double> given_;  // u -> the x it was given as
  std::map<double, double> seen_;   // u -> cost
};

// Whether the hint (a bracket from an earlier search) still brackets the cost.
bool StillBrackets(SearchPoints& f, const std::array<double, 3>& hint, std::string* log) {
  const double a = f.scale.ToU(hint[0]), m = f.scale.ToU(hint[1]),
               c = f.scale.ToU(hint[2]);
  const double fm = f(m);
  const bool hinted = a < m && m < c && fm < f(a) && fm < f(c);
  if (hinted)
    *log += fmt::format("bracket from the last round: [{:.6g}, {:.6g}, {:.6g}]\n",
                        hint[0], hint[1], hint[2]);
  return hinted;
}

// One side is flat (or falling) up to its bound, the other has a higher cost
// (b). A step function may hide its minimum in the gap between that higher
// point and the flat run, which the growing steps jumped: bisects the gap
// until a lower cost appears or the run's edge is found.
void BisectGap(SearchPoints& f, const SearchPoints::Bracket& b, std::string* log) {
  const double low = b.m->second;
  double high_u = b.has_a ? b.a->first : b.c->first;
  double run_u = b.has_a ? std::next(b.a)->first : std::prev(b.c)->first;
  while (!f.NarrowEnough(std::min(high_u, run_u), std::max(high_u, run_u), run_u)) {
    const double q = 0.5 * (high_u + run_u);
    const double fq = f(q);
    *log += fmt::format("gap: cost {:.6g} at {:.6g}\n", fq, f.XOf(q));
    if (fq < low) break;  // bracketed: (the higher point, q, the run)
    (fq > low ? high_u : run_u) = q;
  }
}

// The walk from the start (the header's): steps growing by kGrow in the
// direction of descent until the lowest cost has a higher one on each side or
// each side without one has reached its bound; then the gap of a one-sided
// bracket. Sets out->at_bound when no bracket was found.
void Walk(SearchPoints& f, BracketedSearch* out) {
  double step = f.scale.logs ? std::log(2.0) : (f.hi - f.lo) / 8;
  f(f.u0);
  f(f.u0 < f.hi ? f.u0 + step : f.u0 - step);
  SearchPoints::Bracket b;
  for (;;) {
    b = f.Lowest();
    out->log += fmt::format("walk: lowest cost {:.6g} at {:.6g}\n", b.m->second,
                            f.XOf(b.m->first));
    if (b.has_a && b.has_c) break;
    const double left = f.Leftmost(), right = f.Rightmost();
    int dir = 0;
    if (!b.has_a && left > f.lo) {
      dir = -1;
    } else if (!b.has_c && right < f.hi) {
      dir = 1;
    }
    if (dir == 0) break;  // each side without a higher cost has reached its bound
    step *= kGrow;
    f(dir > 0 ? right + step : left - step);
  }
  if (b.has_a != b.has_c) {
    BisectGap(f, b, &out->log);
    b = f.Lowest();
  }
  out->at_bound = !(b.has_a && b.has_c);
}

}  // namespace

BracketedSearch MinimizeBracketed(const std::function<double(double)>& cost, double lower,
                                  double upper, double start, double tolerance,
                                  int max_iterations,
                                  const std::optional<std::array<double, 3>>& hint) {
  if (!(lower < upper && lower <= start && start <= upper && tolerance > 0))
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        "MinimizeBracketed: needs lower <= start <= upper, tolerance > 0");
  const Scale scale{lower > 0};
  SearchPoints f(cost, lower, upper, start, tolerance, hint);
  BracketedSearch out;
  if (!(hint && StillBrackets(f, *hint, &out.log))) Walk(f, &out);
  const SearchPoints::Bracket b = f.Lowest();
  out.estimate = f.XOf(b.m->first);
  out.cost = b.m->second;
  if (!(b.has_a && b.has_c)) {
    out.at_bound = true;
    out.bracket = {out.estimate, out.estimate, out.estimate};
    return out;
  }

  // Golden section inside the bracket, on the cached values of its three
  // points.
  const GslHandlerOff handler;
  std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)> s(
      gsl_min_fminimizer_alloc(gsl_min_fminimizer_goldensection),
      &gsl_min_fminimizer_free);
  // An exception (an interrupt, an input error at a new point) must not
  // unwind through GSL's C frames: it is kept and rethrown here.
  using Cost = SearchPoints;
  struct Call {
    Cost* cost;
    std::exception_ptr error;
  } call{&f, nullptr};
  gsl_function fn;
  fn.function = [](double u, void* p) {
    Call* c = static_cast<Call*>(p);
    try {
      return (*c->cost)(u);
    } catch (...) {
      c->error = std::current_exception();
      return std::nan("");  // GSL stops with GSL_EBADFUNC
    }
  };
  fn.params = &call;
  if (gsl_min_fminimizer_set_with_values(s.get(), &fn, b.m->first, b.m->second,
                                         b.a->first, b.a->second, b.c->first,
                                         b.c->second) != GSL_SUCCESS)
    throw ComputationError(ComputationError::Reason::kRefused,
                           "MinimizeBracketed: GSL refused a strict bracket");
  auto narrow = [&] {
    return f.NarrowEnough(gsl_min_fminimizer_x_lower(s.get()),
                          gsl_min_fminimizer_x_upper(s.get()),
                          gsl_min_fminimizer_x_minimum(s.get()));
  };
  while (!narrow() && out.iterations < max_iterations) {
    const int status = gsl_min_fminimizer_iterate(s.get());
    if (call.error) std::rethrow_exception(call.error);
    if (status != GSL_SUCCESS) break;
    ++out.iterations;
    out.log += fmt::format("golden {}: [{:.6g}, {:.6g}], lowest cost {:.6g} at {:.6g}\n",
                           out.iterations, scale.ToX(gsl_min_fminimizer_x_lower(s.get())),
                           scale.ToX(gsl_min_fminimizer_x_upper(s.get())),
                           gsl_min_fminimizer_f_minimum(s.get()),
                           scale.ToX(gsl_min_fminimizer_x_minimum(s.get())));
  }
  out.converged = narrow();
  out.estimate = f.XOf(gsl_min_fminimizer_x_minimum(s.get()));
  out.cost = gsl_min_fminimizer_f_minimum(s.get());
  out.bracket = {f.XOf(gsl_min_fminimizer_x_lower(s.get())), out.estimate,
                 f.XOf(gsl_min_fminimizer_x_upper(s.get()))};
  return out;
}

ProfileInterval ProfileBounds(const std::function<double(double)>& cost, double lower,
                              double upper, double estimate, double cost_at_estimate,
                              double rise, double first_step, double tolerance) {
  if (!(lower <= estimate && estimate <= upper && rise > 0 && first_step > 0 &&
        tolerance > 0))
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        "ProfileBounds: needs lower <= estimate <= upper and positive rise, step, "
        "tolerance");
  const Scale scale{lower > 0};
  const double lo = scale.ToU(lower), hi = scale.ToU(upper), u0 = scale.ToU(estimate);
  const double limit = cost_at_estimate + rise;
  ProfileInterval out;
  // Whether the cost at u is within the rise; the bounds at their exact x.
  const auto inside = [&](double u) {
    const double x = u <= lo ? lower : u >= hi ? upper : scale.ToX(u);
    const double c = cost(x);
    ++out.evaluations;
    out.log += fmt::format("profile: cost {:.6g} at {:.6g}\n", c, x);
    return std::isfinite(c) && c <= limit;
  };
  // In x, steps and the tolerance are fractions of the estimate's magnitude,
  // or of a thousandth of the range about an estimate at or near 0.
  const double magnitude = std::max(std::fabs(estimate), 1e-3 * (upper - lower));
  const double step0 = scale.logs ? std::log1p(first_step) : first_step * magnitude;
  const double width = scale.logs ? std::log1p(tolerance) : tolerance * magnitude;
  // One side (dir -1 or +1): the end in u, and whether it is the bound.
  const auto side = [&](int dir, bool* open) {
    const double bound = dir < 0 ? lo : hi;
    double in = u0, step = step0;
    for (;;) {
      const double u = dir < 0 ? std::max(in - step, lo) : std::min(in + step, hi);
      if (u == in) {  // the estimate is at the bound
        *open = true;
        return bound;
      }
      if (!inside(u)) {
        double out_u = u;
        while (std::fabs(out_u - in) > width) {
          const double mid = 0.5 * (in + out_u);
          if (mid == in || mid == out_u) break;  // adjacent doubles
          (inside(mid) ? in : out_u) = mid;
        }
        return 0.5 * (in + out_u);
      }
      in = u;
      if (u == bound) {
        *open = true;
        return bound;
      }
      step *= kGrow;
    }
  };
  const double a = side(-1, &out.open_lower), b = side(1, &out.open_upper);
  out.lower = out.open_lower ? lower : scale.ToX(a);
  out.upper = out.open_upper ? upper : scale.ToX(b);
  return out;
}

}  // namespace vahf::calibrate
