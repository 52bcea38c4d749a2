#include "vahf/sim/internal/simbody_trial.h"

#include <fmt/format.h>

#include "vahf/sim/internal/decisions.h"

namespace vahf::sim::internal {
namespace {

Vector3d ToEigen(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }
SimTK::Vec3 ToSimTK(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Matrix3d ToEigen(const SimTK::Rotation& r) {
  Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = r[i][j];
  return m;
}
SimTK::Rotation ToSimTK(const Matrix3d& m) {
  SimTK::Mat33 a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = m(i, j);
  return SimTK::Rotation(a, true);
}

}  // namespace

// The contact and operator loads (TrialModel::LoadsAt) at the current state
// and the held decision, kept in a cache entry of that state so that an
// accepted step or a sample reads them without a second contact evaluation.
class SimbodyTrial::LoadsElement : public SimTK::Force::Custom::Implementation {
 public:
  explicit LoadsElement(SimbodyTrial* t) : t_(t) {}

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
    TrialContext& c = t_->c_;
    const contact::RigidMotion m = t_->MotionOf(s);
    Loads& loads =
        static_cast<SimTK::Value<Loads>&>(t_->forces_.updCacheEntry(s, t_->loads_index_))
            .upd();
    loads = Loads{};
    if (!IsFinite(m)) {  // no force from garbage; the step will be rejected or caught
      c.warnings.Note(WarningKind::kNonFiniteState, s.getTime(),
                      "non-finite pose or velocity in a force evaluation");
      return;
    }
    loads = c.LoadsAt(m, t_->HeldDecision(s));
    body_forces[t_->body_] +=
        SimTK::SpatialVec(ToSimTK(loads.torque), ToSimTK(loads.force));
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

  void realizeTopology(SimTK::State& s) const override {
    t_->decision_index_ = t_->forces_.allocateDiscreteVariable(
        s, SimTK::Stage::Dynamics, new SimTK::Value<Decision>(Decision{}));
    t_->loads_index_ =
        t_->forces_.allocateCacheEntry(s, SimTK::Stage::Velocity, SimTK::Stage::Dynamics,
                                       new SimTK::Value<Loads>(Loads{}));
  }

 private:
  SimbodyTrial* t_;
};

class SimbodyTrial::DecisionHandler : public SimTK::PeriodicEventHandler {
 public:
  DecisionHandler(SimbodyTrial* t, double interval)
      : SimTK::PeriodicEventHandler(interval), t_(t) {}
  void handleEvent(SimTK::State& s, SimTK::Real, bool& terminate) const override {
    t_->Decide(s);
    terminate = t_->c_.ended.has_value();
  }

 private:
  SimbodyTrial* t_;
};

// Completion witness: max(|T - T_t| / d_th, angle / angle_th) - 1 falls through
// zero when both are below their thresholds; Simbody locates that instant.
class SimbodyTrial::CompletionTrigger : public SimTK::TriggeredEventHandler {
 public:
  explicit CompletionTrigger(SimbodyTrial* t)
      : SimTK::TriggeredEventHandler(SimTK::Stage::Position), t_(t) {
    getTriggerInfo().setTriggerOnRisingSignTransition(false);
  }
  SimTK::Real getValue(const SimTK::State& s) const override {
    return t_->c_.model.CompletionWitness(t_->PoseOf(s));
  }
  void handleEvent(SimTK::State& s, SimTK::Real, bool& terminate) const override {
    TrialContext& c = t_->c_;
    const auto& sim = c.params().simulation;
    c.ended = Status::kCompleted;
    c.completion_time = s.getTime();
    c.completion_row = t_->FinalRow(s);  // Table 1's instant d, at this very state
    c.detail = fmt::format("within {} m and {} deg of the target",
                           sim.completion_distance, sim.completion_angle_deg);
    terminate = true;
  }

 private:
  SimbodyTrial* t_;
};

SimbodyTrial::SimbodyTrial(TrialContext& c) : c_(c), matter_(system_), forces_(system_) {
  const TrialModel& model = c.model;
  SimTK::Force::UniformGravity gravity(forces_, matter_, ToSimTK(model.gravity));
  const Matrix3d& i = model.inertia_body;
  const SimTK::Inertia inertia_com(SimTK::Vec3(i(0, 0), i(1, 1), i(2, 2)),
                                   SimTK::Vec3(i(0, 1), i(0, 2), i(1, 2)));
  const SimTK::Body::Rigid body(SimTK::MassProperties(
      model.mass, ToSimTK(model.com),
      inertia_com.shiftFromMassCenter(-ToSimTK(model.com), model.mass)));
  SimTK::MobilizedBody::Free mobod(matter_.Ground(), SimTK::Transform(), body,
                                   SimTK::Transform());
  body_ = mobod.getMobilizedBodyIndex();
  SimTK::Force::Custom loads(forces_, new LoadsElement(this));
  system_.addEventHandler(
      new DecisionHandler(this, model.params.simulation.decision_interval));
  system_.addEventHandler(new CompletionTrigger(this));

  initial_ = system_.realizeTopology();
  const scene::Pose& start = model.initial;
  mobod.setQToFitTransform(
      initial_, SimTK::Transform(ToSimTK(start.Rotation()), ToSimTK(start.position)));
  Decide(initial_);
}

contact::RigidMotion SimbodyTrial::PoseOf(const SimTK::State& s) const {
  const SimTK::Transform& x = matter_.getMobilizedBody(body_).getBodyTransform(s);
  contact::RigidMotion m;
  m.pose.linear() = ToEigen(x.R());
  m.pose.translation() = ToEigen(x.p());
  return m;
}

contact::RigidMotion SimbodyTrial::MotionOf(const SimTK::State& s) const {
  contact::RigidMotion m = PoseOf(s);
  const SimTK::SpatialVec& v = matter_.getMobilizedBody(body_).getBodyVelocity(s);
  m.angular_velocity = ToEigen(v[0]);
  m.velocity = ToEigen(v[1]);
  return m;
}

const Decision& SimbodyTrial::HeldDecision(const SimTK::State& s) const {
  // The variable was allocated as a Value<Decision> in realizeTopology, so a
  // static cast is safe; Value::downcast's dynamic_cast cost 8 % of a trial.
  return static_cast<const SimTK::Value<Decision>&>(
             forces_.getDiscreteVariable(s, decision_index_))
      .get();
}

const Loads& SimbodyTrial::LoadsOf(const SimTK::State& s) const {
  return static_cast<const SimTK::Value<Loads>&>(forces_.getCacheEntry(s, loads_index_))
      .get();
}

void SimbodyTrial::Decide(SimTK::State& s) {
  system_.realize(s, SimTK::Stage::Velocity);
  if (const std::optional<Decision> d = internal::Decide(c_, s.getTime(), MotionOf(s)))
    static_cast<SimTK::Value<Decision>&>(forces_.updDiscreteVariable(s, decision_index_))
        .upd() = *d;
}

TraceRow SimbodyTrial::FinalRow(SimTK::State& s) {
  system_.realize(s, SimTK::Stage::Velocity);
  return internal::FinalRow(c_, s.getTime(), MotionOf(s));
}

}  // namespace vahf::sim::internal
