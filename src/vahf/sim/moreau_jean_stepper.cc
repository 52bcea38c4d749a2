// The MoreauJean stepper (scene/steppers.def; docs/design.md decision 16): a
// core of the shared driver (stepper_core.h) that takes fixed steps of
// Moreau-Jean's nonsmooth time stepping (internal/moreau_jean.h) on the
// exact contact points of the trial model's contact
// (contact::ContactModel::AddContactPoints), Coulomb's law set-valued, so a
// part held inside its friction cone does not move.
//
// Per step: the contact points within the margin, the larger of the
// penetration bound and 1.5 times the farthest point's travel over the step
// at the larger of its speed now and its speed under the smooth loads alone;
// the smooth loads (the operator, the oil film) and their Jacobian at the
// step's start, the operator feeling the previous step's net contact force
// (its impulse over the step: Eqs. 7-8 read a well-defined quantity however
// many points carry it); the step; the contact force for the next.
//
// The step is simulation/moreau_jean_step, shortened only to land on a
// decision instant and, after the driver takes a step back (a contact
// deepened by more than a quarter of the barrier within it: a contact met
// faster than the margin allowed), to the driver's cap, doubled at each
// step kept until it is the full step again.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "vahf/core/error.h"
#include "vahf/scene/stepper_catalogue.h"
#include "vahf/sim/internal/moreau_jean.h"
#include "vahf/sim/internal/trial_context.h"
#include "vahf/sim/rigid_body.h"
#include "vahf/sim/stepper_core.h"

namespace vahf::sim::internal {
namespace {

namespace stepper_settings = scene::stepper_settings;

// The margin's factor on one step's travel (docs/physics.md, "Nonsmooth
// stepping"): a point that can close its gap within the step is a candidate.
constexpr double kMarginTravel = 1.5;

// The most contact points one step's problem takes: the largest problem the
// solver takes dense (kLargestDenseContacts); its sparse path was ten times
// slower (7.6 against 0.66 ms a problem on the piston rod's). Beyond it the
// points with the largest gaps are left out, the least likely to close
// within the step; the driver's depth checks still see every contact.
constexpr std::size_t kMaxPoints = kLargestDenseContacts;

// Keeps the kMaxPoints points of least gap, in their order (ties: the
// earlier first).
void KeepClosest(std::vector<contact::ContactPoint>* points) {
  if (points->size() <= kMaxPoints) return;
  std::vector<std::size_t> order(points->size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return (*points)[a].gap < (*points)[b].gap;
  });
  order.resize(kMaxPoints);
  std::sort(order.begin(), order.end());
  std::vector<contact::ContactPoint> kept;
  for (std::size_t i : order) kept.push_back((*points)[i]);
  *points = std::move(kept);
}

class MoreauJeanCore : public StepperCore {
 public:
  MoreauJeanCore(RightHandSide& rhs, const BodyState& start)
      : rhs_(rhs), c_(rhs.context()), y_(start), prev_y_(start) {
    const auto& sim = rhs.settings();
    h_max_ = sim.stepper_values.Get(stepper_settings::moreau_jean_step);
    settings_.theta = sim.stepper_values.Get(stepper_settings::moreau_jean_theta);
    settings_.solver.tolerance =
        sim.stepper_values.Get(stepper_settings::moreau_jean_tolerance);
    settings_.restitution = c_.params().contact.restitution;
    settings_.compliance =
        sim.stepper_values.Get(stepper_settings::moreau_jean_compliance);
    settings_.overlap_step = h_max_;
    felt_time_ = sim.stepper_values.Get(stepper_settings::moreau_jean_felt_time);
    const TrialModel& model = c_.model;
    body_ = {model.mass, model.inertia_body, model.com};
    cap_ = h_max_;
    c_.nonsmooth_contact = &felt_;
  }
  ~MoreauJeanCore() override { c_.nonsmooth_contact = nullptr; }

  void Reset(double t, const BodyState& y) override {
    t_ = t, y_ = y, prev_y_ = y, last_h_ = 0;
  }

  void Retake(double t, const BodyState& y, double max_step) override {
    t_ = t, y_ = y, prev_y_ = y, last_h_ = 0;
    felt_ = felt_before_;
    cap_ = std::min(cap_, max_step);
    ++retakes_;
  }

  void Kept() override { cap_ = std::min(h_max_, 2 * cap_); }

  StepOutcome StepTo(double stop) override {
    StepOutcome o;
    double h = std::min(cap_, stop - t_);
    // A remainder below a thousandth of the step joins this one.
    if (stop - t_ - h < 1e-3 * h) h = stop - t_;
    o.h = h;
    try {
      Step(h);
    } catch (const ComputationError& e) {
      o.kind = StepOutcome::kFailed;
      o.t = t_;
      o.detail = fmt::format("MoreauJean stopped at t = {} s: {}", t_, e.what());
      return o;
    }
    t_ = h == stop - t_ ? stop : t_ + h;
    o.t = t_;
    o.retries = retakes_;
    o.kind = t_ >= stop ? StepOutcome::kReachedStop : StepOutcome::kStepped;
    return o;
  }

  BodyState State() const override { return y_; }

  // The step's secant: the path between its ends is the straight one the
  // step's positions took (u_theta held over it).
  BodyState Slope(double) override {
    if (!(last_h_ > 0)) return BodyState::Zero();
    return (y_ - prev_y_) / last_h_;
  }

  std::string RetryDetail(std::int64_t retries) const override {
    return fmt::format("{} steps retaken shorter", retries);
  }

  void SetCounters(TrialCounters* counters) override {
    counters->steps_taken = steps_;
    counters->steps_attempted = steps_ + retakes_;
    counters->realizations = steps_ + retakes_;
    counters->jacobian_evaluations = steps_ + retakes_;
    counters->convergence_failures = unconverged_;
  }

 private:
  // The margin of the contact points for a step of h from m: see the file's
  // comment.
  double Margin(const contact::RigidMotion& m, double gained, double h) const {
    const TrialModel& model = c_.model;
    const double speed =
        m.velocity.norm() + model.bounding_radius * m.angular_velocity.norm();
    return std::max(model.penetration_bound, kMarginTravel * h * (speed + gained));
  }

  // The speed the smooth loads alone add to any point within a step of h
  // (gravity too), m/s.
  double Gained(const SmoothLoads& loads, double h) const {
    const TrialModel& model = c_.model;
    return h * ((loads.force / model.mass + model.gravity).norm() +
                model.bounding_radius * loads.torque.norm() /
                    model.inertia_body.diagonal().minCoeff());
  }

  // Leaves out the points whose gap the step cannot close: farther than the
  // margin at the speed the point approaches along its normal (an axial
  // slide closes no radial gap) plus what the loads add.
  void KeepClosing(const contact::RigidMotion& m, double gained, double h) {
    const double bound = c_.model.penetration_bound;
    std::size_t kept = 0;
    for (const contact::ContactPoint& p : points_) {
      const double approach =
          std::max(0.0, -p.normal.dot(m.velocity + m.angular_velocity.cross(p.r)));
      if (p.gap <= std::max(bound, kMarginTravel * h * (approach + gained)))
        points_[kept++] = p;
    }
    points_.resize(kept);
  }

  SmoothLoads LoadsAt(const contact::RigidMotion& m) {
    const TrialModel& model = c_.model;
    contact::ContactJacobian cj;
    contact::ContactForces film;
    if (model.contact.model) {
      const PhaseTimer timer(c_.Timing(&PhaseSeconds::contact));
      film = model.contact.model->SmoothLoads(m, c_.contact_counters, &cj);
    }
    Loads loads;
    loads.contact = felt_;
    Eigen::Vector3d torque;
    {
      const PhaseTimer timer(c_.Timing(&PhaseSeconds::hand));
      model.OperatorLoad(m, rhs_.held(), felt_, &loads.assembly_force, &torque);
    }
    SmoothLoads out;
    out.force = loads.assembly_force + film.film_force;
    out.torque = torque + film.torque;
    const PhaseTimer timer(c_.Timing(&PhaseSeconds::jacobian));
    out.jacobian = model.LoadJacobianAt(m, rhs_.held(), loads, cj);
    return out;
  }

  // The contact the operator feels after a step of h: the step's impulses
  // over h through the first-order lag of felt_time_ (its exact step), or
  // as they are at 0.
  void Feel(const MoreauJeanStepResult& r, double h) {
    const Eigen::Vector3d normal = r.normal_impulse / h,
                          friction = r.friction_impulse / h;
    if (felt_time_ > 0) {
      const double a = -std::expm1(-h / felt_time_);
      felt_.normal_force += a * (normal - felt_.normal_force);
      felt_.friction_force += a * (friction - felt_.friction_force);
    } else {  // exactly the step's, not old + (new - old) rounded
      felt_.normal_force = normal;
      felt_.friction_force = friction;
    }
    felt_.rim_points_in_contact = r.loaded_points;
  }

  void Step(double h) {
    const TrialModel& model = c_.model;
    const contact::RigidMotion m = MotionOf(y_);
    const SmoothLoads loads = LoadsAt(m);
    points_.clear();
    if (model.contact.model) {
      const PhaseTimer timer(c_.Timing(&PhaseSeconds::contact));
      const double gained = Gained(loads, h);
      VAHF_CHECK(model.contact.model->AddContactPoints(m, Margin(m, gained, h),
                                                       c_.contact_counters, &points_),
                 "MoreauJean on a contact model without points: the trial model "
                 "should have refused it");
      KeepClosing(m, gained, h);
      KeepClosest(&points_);
    }
    MoreauJeanStepResult r;
    {
      const PhaseTimer timer(c_.Timing(&PhaseSeconds::linear_algebra));
      r = MoreauJeanStep(body_, y_, h, loads, model.gravity, points_, settings_,
                         &reactions_);
    }
    if (!r.solve.converged) {
      ++unconverged_;
      c_.warnings.Note(
          WarningKind::kContactSolver, t_ + h,
          fmt::format("{} contact points: {}", points_.size(), r.solve.detail));
    }
    felt_before_ = felt_;
    Feel(r, h);
    reactions_ = std::move(r.reactions);
    prev_y_ = y_;
    y_ = r.y;
    last_h_ = h;
    ++steps_;
  }

  RightHandSide& rhs_;
  TrialContext& c_;
  BodyInertia body_;
  MoreauJeanSettings settings_;
  double h_max_ = 0, cap_ = 0, felt_time_ = 0;
  double t_ = 0, last_h_ = 0;
  BodyState y_, prev_y_;
  std::vector<contact::ContactPoint> points_;
  Eigen::VectorXd reactions_;  // the last step's, to start the next solve
  // The contact force the operator feels (the last step's), and the one
  // before it, for a step taken back.
  contact::ContactForces felt_, felt_before_;
  std::int64_t steps_ = 0, retakes_ = 0, unconverged_ = 0;
};

}  // namespace

std::unique_ptr<StepperCore> MakeMoreauJeanCore(RightHandSide& rhs,
                                                const BodyState& start) {
  return std::make_unique<MoreauJeanCore>(rhs, start);
}

}  // namespace vahf::sim::internal
