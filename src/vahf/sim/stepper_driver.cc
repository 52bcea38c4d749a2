#include "vahf/sim/internal/stepper_driver.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <memory>

#include "vahf/sim/internal/decisions.h"
#include "vahf/sim/internal/step_checks.h"
#include "vahf/sim/rigid_body.h"

namespace vahf::sim::internal {
namespace {

// The most one accepted step may deepen the contact, as a fraction of the
// hardening barrier's depth b (contact_params.h). A quarter: the barrier's
// factor (1 - x / b)^-2 is under 1.8 over it, so a step within it has met
// the law's gentle part, and a step past it has jumped to where the
// stiffness climbs without bound.
constexpr double kDeepeningLimit = 0.25;

// The deepest contact a pass may miss, as a fraction of the hardening
// barrier's depth b. The exact rim contact finds every dip of a rim into a
// solid but one narrower than its scan's finest interval whose ends' slopes
// do not bracket it, which is shallower than the slope bound over that
// interval (contact/rim_arcs.h): about 0.2 um at the scenes' tilts of a
// degree, 1 um at 5 deg (a rim of 32.5 mm, 2 pi / 8 / 2^10 rad), a fifth to a
// third of the cylinder's 3.4 um barrier; the deepest points of the dips it
// finds to 1e-10 m. The same bits as a pass at every step over the piston
// rod's seeds 101-130 and the peg's seed 101 (the test
// CvodeStepper.TheDepthBoundSparesPassesAndChangesNoBit).
constexpr double kDepthMargin = 0.2;

// How far any point within `radius` of a rigid part's frame origin moves
// between poses a and b, at most: the origin's displacement plus the radius
// times the rotations' difference (its spectral norm, at most the Frobenius).
double PoseTravel(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double radius) {
  return (a.translation() - b.translation()).norm() +
         radius * (a.linear() - b.linear()).norm();
}

// The contact's depth at a state for the step checks, m: a pass's, or a
// stand-in that a pass would give a value within [least, most] of
// (Drive::DepthAt).
struct Depth {
  double value = 0, least = 0, most = 0;
  static Depth Pass(double d) { return {d, d, d}; }
};

// How far a step from y0 to y1 moves the part's farthest point, about: the
// origin's displacement plus the radius times the turn (twice the
// quaternion's change).
double Travel(const BodyState& y0, const BodyState& y1, double radius) {
  return (y1.segment<3>(0) - y0.segment<3>(0)).norm() +
         2 * radius * (y1.segment<4>(3) - y0.segment<4>(3)).norm();
}

// The cubic Hermite interpolant at ts in [t0, t1] of states y0, y1 with
// slopes d0, d1: exact for cubics, and fixed by the step's two ends and slopes.
BodyState Hermite(double t0, const BodyState& y0, const BodyState& d0, double t1,
                  const BodyState& y1, const BodyState& d1, double ts) {
  const double h = t1 - t0;
  if (!(h > 0)) return y1;
  const double s = (ts - t0) / h, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * d0 +
         (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * h * d1;
}

// One trial stepped by a core from its first decision: step by step to each
// decision instant, every accepted step checked and sampled, the core reset
// at each decision.
class Drive {
 public:
  Drive(TrialContext& c, RightHandSide& rhs, StepperCore& core, double sample_interval)
      : c_(c),
        sim_(c.params().simulation),
        rhs_(rhs),
        core_(core),
        sample_interval_(sample_interval),
        deepening_limit_(kDeepeningLimit * c.model.contact.barrier_depth),
        depth_margin_(kDepthMargin * c.model.contact.barrier_depth),
        path_(deepening_limit_ > 0 || sample_interval > 0 || !core.FindsRoots()),
        checks_(c),
        y_(core.State()),
        kept_y_(y_) {}

  // Steps to completion, an ending or the time limit: the time reached.
  double Run(std::optional<TraceRow>* final_row, TrialCounters* counters) {
    const double limit = sim_.time_limit, interval = sim_.decision_interval;
    for (std::int64_t i = 1; !c_.ended && t_ < limit; ++i) {
      StepTo(std::min(static_cast<double>(i) * interval, limit));
      if (c_.ended || t_ >= limit) break;
      if (!Restart()) break;
    }
    core_.SetCounters(counters);
    if (c_.completion_row)
      *final_row = c_.completion_row;
    else
      *final_row = FinalRow(c_, t_, MotionOf(y_));
    return t_;
  }

 private:
  // The core's steps up to `stop`, a decision instant or the time limit.
  void StepTo(double stop) {
    checks_.Restarted();
    while (!c_.ended) {
      const StepOutcome o = core_.StepTo(stop);
      t_ = o.t;
      y_ = core_.State();
      if (o.kind == StepOutcome::kFailed) {
        c_.ended = Status::kNumericalFailure;
        c_.detail = o.detail;
        c_.warnings.Note(WarningKind::kIntegratorFailure, t_, c_.detail);
        break;
      }
      if (!Step(o, stop)) break;
    }
  }

  // The step the core took to t_: taken back, or checked, sampled and kept.
  // False when stepping to `stop` is over.
  bool Step(const StepOutcome& o, double stop) {
    const contact::RigidMotion m = MotionOf(y_);
    Depth depth = IsFinite(m) ? DepthAt(m) : Depth{};
    const BodyState slope = Slope();
    if (TakeBack(y_, slope, &depth, o.h)) {
      core_.Retake(kept_t_, kept_y_, 0.25 * o.h);
      y_ = kept_y_, t_ = kept_t_;
      checks_.Restarted();
      return true;
    }
    core_.Kept();
    if (!checks_.Accepted(t_, m, depth.value, o.h, o.retries,
                          [&] { return core_.RetryDetail(o.retries); }))
      return false;
    // Completion within the step, for a core that does not find it itself.
    const std::optional<double> within =
        core_.FindsRoots() ? std::nullopt : CompletionOnPath(m, slope);
    Sample(slope, within.value_or(t_));
    const contact::RigidMotion end = within ? MotionOf(PathAt(y_, slope, *within)) : m;
    kept_y_ = y_, kept_t_ = t_, kept_depth_ = depth, kept_slope_ = slope;
    if (o.kind == StepOutcome::kCompleted || within) {
      t_ = within.value_or(t_);
      Complete(t_, end);
    }
    return !(o.kind == StepOutcome::kReachedStop || t_ >= stop);
  }

  // Samples in (before, end] on the step's Hermite path, the one checked
  // above, rather than a core's own interpolant.
  void Sample(const BodyState& slope, double end) {
    for (; sample_interval_ > 0; ++next_sample_) {
      const double ts = static_cast<double>(next_sample_) * sample_interval_;
      if (ts > end || ts >= sim_.time_limit) break;
      const contact::RigidMotion ms = MotionOf(PathAt(y_, slope, ts));
      c_.samples.push_back(
          c_.SampleRow(ts, ms, c_.LoadsAt(ms, rhs_.held()), rhs_.held().psi));
    }
  }

  void Complete(double t, const contact::RigidMotion& m) {
    c_.ended = Status::kCompleted;
    c_.completion_time = t;
    c_.completion_row = FinalRow(c_, t, m);  // Table 1's instant d, at this state
    c_.detail = fmt::format("within {} m and {} deg of the target",
                            sim_.completion_distance, sim_.completion_angle_deg);
  }

  // Where the completion witness (TrialModel::CompletionWitness) falls
  // through zero on the step's path, from the kept state to m at t_: the
  // earliest time found within, by bisection to kCompletionTolerance;
  // nothing when the step does not end within or began there.
  std::optional<double> CompletionOnPath(const contact::RigidMotion& m,
                                         const BodyState& slope) const {
    const TrialModel& model = c_.model;
    if (!(model.CompletionWitness(m) <= 0) ||
        !(model.CompletionWitness(MotionOf(kept_y_)) > 0))
      return std::nullopt;
    double outside = kept_t_, within = t_;
    while (within - outside > kCompletionTolerance) {
      const double mid = outside + 0.5 * (within - outside);
      if (mid <= outside || mid >= within) break;  // no double between them
      const BodyState ym = PathAt(y_, slope, mid);
      (model.CompletionWitness(MotionOf(ym)) <= 0 ? within : outside) = mid;
    }
    return within;
  }

  // The contact's depth at the accepted state m, for the checks: what they
  // need of it. A rigid part's contact deepens no faster than its points
  // move (the signed distance is 1-Lipschitz), and a pass misses no contact
  // deeper than kDepthMargin; so from the last contact evaluated (as a
  // rule the corrector's last iterate, within its tolerance of m) a pass at
  // m would find a depth within a range: the travel between the two poses
  // either side of the depth there (below the margin, down to zero). Where
  // the whole range lies short of the deepest contact so far and of the
  // penetration bound, the depth there stands in for the pass, with its
  // range (Depth), and the take-back decides from the range where it can
  // (TakeBack): the checks decide as passes would, the same bits, with a
  // pass at every accepted step spared in about 95 % of a piston-rod trial's
  // steps. Otherwise, and for a model without the barrier (the point
  // shell's depth is sampled, not Lipschitz), a pass at m: the contact
  // alone, not the operator's load.
  Depth DepthAt(const contact::RigidMotion& m) {
    const double near = c_.evaluated_depth;
    if (near >= 0 && depth_margin_ > 0 && !c_.depth_pass_every_step) {
      const double travel =
          PoseTravel(c_.evaluated_pose, m.pose, c_.model.bounding_radius);
      // A pass may miss a contact shallower than the margin, none deeper.
      const double most = std::max(near, depth_margin_) + travel;
      double matters = c_.max_penetration;
      if (c_.model.penetration_bound > 0)
        matters = std::min(matters, c_.model.penetration_bound);
      if (most < matters)
        return {near, near - travel >= depth_margin_ ? near - travel : 0.0, most};
    }
    return Depth::Pass(c_.ContactAt(m).max_depth);
  }

  // d from a pass at m, when it is a stand-in.
  void Settle(Depth* d, const contact::RigidMotion& m) {
    if (d->least < d->most) *d = Depth::Pass(c_.ContactAt(m).max_depth);
  }

  // The slope at the step's end, and at its start once a step from it has
  // been taken since a (re)start: the step's cubic Hermite is the path
  // checked, sampled and searched for completion, when any is asked for;
  // zero otherwise.
  BodyState Slope() {
    BodyState slope = BodyState::Zero();
    if (path_) {
      slope = core_.Slope(t_);
      if (!kept_slope_known_) {  // the first step since a (re)start
        kept_slope_ = core_.Slope(kept_t_);
        kept_slope_known_ = true;
      }
    }
    return slope;
  }

  // The state at ts on the step's path from the kept state to y at t_, its
  // quaternion normalised.
  BodyState PathAt(const BodyState& y, const BodyState& slope, double ts) const {
    BodyState ys = Hermite(kept_t_, kept_y_, kept_slope_, t_, y, slope, ts);
    NormaliseQuaternion(&ys);
    return ys;
  }

  // A step that carries the contact deeper than kDeepeningLimit of the
  // barrier has jumped the contact's onset: an error test in units of
  // position cannot see micrometres, and the state it accepted lies in the
  // barrier's steep part, where the next steps' corrector fails
  // (docs/physics.md, Integrators). So has a step whose path passes through a
  // contact that neither end touches (the peg's rim grazing the bore's
  // chamfer within one step, 14 um deep between clear ends): its midpoint is
  // checked whenever the step moves the part's farthest point by more than
  // the limit, which no step in contact does. Either is taken back and
  // retaken with a quarter of the step; the depth is continuous in time, so
  // the retakes end. Not below the step floor.
  // A depth standing in for a pass (DepthAt) takes the decisions the pass
  // would: from its range where that settles them, otherwise from the pass.
  bool TakeBack(const BodyState& y, const BodyState& slope, Depth* depth, double h) {
    bool retake = false;
    if (deepening_limit_ > 0 && h > sim_.step_floor) {
      const double limit = deepening_limit_;
      // Each test is made at both ends of the depths' ranges; where the two
      // disagree, passes settle the stand-ins.
      const auto settle = [&] {
        Settle(depth, MotionOf(y));
        Settle(&kept_depth_, MotionOf(kept_y_));
      };
      // The step's end deeper than its start by more than the limit.
      if ((depth->most - kept_depth_.least > limit) !=
          (depth->least - kept_depth_.most > limit))
        settle();
      retake = depth->least - kept_depth_.most > limit;
      if (!retake && Travel(kept_y_, y, c_.model.bounding_radius) > limit) {
        const contact::RigidMotion mid =
            MotionOf(PathAt(y, slope, kept_t_ + 0.5 * (t_ - kept_t_)));
        if (IsFinite(mid)) {
          // Its midpoint deeper than both ends by more than the limit.
          const double deepest = c_.ContactAt(mid).max_depth;
          const auto over = [&](double a, double b) {
            return deepest - std::max(a, b) > limit;
          };
          if (over(depth->least, kept_depth_.least) !=
              over(depth->most, kept_depth_.most))
            settle();
          retake = over(depth->most, kept_depth_.most);
        }
      }
    }
    return retake;
  }

  // The decision at t_i: what the operator holds from now on; the
  // right-hand side changed, so the core restarts from this state. False
  // when the decision ended the trial.
  bool Restart() {
    NormaliseQuaternion(&y_);
    if (const std::optional<Decision> d = Decide(c_, t_, MotionOf(y_))) rhs_.Hold(*d);
    if (c_.ended) return false;
    core_.Reset(t_, y_);
    kept_y_ = y_, kept_t_ = t_, kept_slope_known_ = false;
    return true;
  }

  TrialContext& c_;
  const scene::SimulationParams& sim_;
  RightHandSide& rhs_;
  StepperCore& core_;
  const double sample_interval_;
  const double deepening_limit_;
  const double depth_margin_;
  const bool path_;  // the steps' Hermite paths are asked for
  StepChecks checks_;
  std::int64_t next_sample_ = 1;
  double t_ = 0;
  BodyState y_;  // the state at t_
  // The last step kept, for a step taken back.
  BodyState kept_y_;
  double kept_t_ = 0;
  Depth kept_depth_;
  // Its slope, once a step from it has been taken since a (re)start.
  BodyState kept_slope_ = BodyState::Zero();
  bool kept_slope_known_ = false;
};

}  // namespace

double DriveTrial(TrialContext& c, CoreFactory make, double sample_interval,
                  std::optional<TraceRow>* final_row, TrialCounters* counters) {
  contact::RigidMotion start;
  start.pose = c.model.initial.Transform();
  const std::optional<Decision> first = Decide(c, 0.0, start);
  if (c.ended || !first) {  // ended at the first decision
    *final_row = FinalRow(c, 0.0, start);
    return 0.0;
  }
  RightHandSide rhs(c);  // outlives the core, which integrates it
  rhs.Hold(*first);
  const std::unique_ptr<StepperCore> core = make(rhs, StateOf(start));
  c.integrated = true;
  Drive drive(c, rhs, *core, sample_interval);
  return drive.Run(final_row, counters);
}

}  // namespace vahf::sim::internal
