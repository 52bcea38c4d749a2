// A trial's numerical health and its dense trace: sampling reads the
// integrator's interpolant and changes no bit of the result; the warnings
// record counts contact deeper than the bound (a soft contact that cannot
// resolve the 50 um fit) and stays empty where nothing went wrong; a trial
// that ends at its first decision reports zero integrator counters, never
// the values of an integrator that never stepped; a clearance is found where
// the scene has a fit and not where it has none.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "vahf/scene/scene_loader.h"
#include "vahf/scene/stepper_catalogue.h"
#include "vahf/sim/trace_csv.h"
#include "vahf/sim/trial.h"

namespace vahf::sim {
namespace {

scene::Scene LoadExample(const std::string& name) {
  return scene::LoadScene(std::string(VAHF_SOURCE_DIR) + "/experiments/scenes/" + name);
}

constexpr double kSampleInterval = 0.5e-3;

// Seed 1 of `s` without samples (a) and with a sample every 0.5 ms (b); both
// complete, at the same instant to the bit, in the same number of steps.
struct PlainAndSampled {
  TrialResult a, b;
};
PlainAndSampled RunBoth(const scene::Scene& s, bool record_trace) {
  TrialOptions plain, sampled;
  plain.record_trace = sampled.record_trace = record_trace;
  sampled.sample_interval = kSampleInterval;
  PlainAndSampled r{RunTrial(s, {1, 0}, plain), RunTrial(s, {1, 0}, sampled)};
  EXPECT_EQ(r.a.status, Status::kCompleted) << r.a.detail;
  EXPECT_EQ(r.a.completion_time, r.b.completion_time);  // bit for bit
  EXPECT_EQ(r.a.counters.steps_taken, r.b.counters.steps_taken);
  EXPECT_EQ(r.a.final_row.position, r.b.final_row.position);
  return r;
}

TEST(TrialHealth, SamplesDoNotChangeTheTrajectory) {
  const auto [a, b] = RunBoth(LoadExample("peg_in_hole_shell.json"), true);
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (std::size_t i = 0; i < a.trace.size(); ++i) {
    EXPECT_EQ(a.trace[i].position, b.trace[i].position) << "decision " << i;
    EXPECT_EQ(a.trace[i].velocity, b.trace[i].velocity) << "decision " << i;
  }
  EXPECT_TRUE(a.samples.empty());
  // One row per multiple of the interval before the end, at that instant.
  ASSERT_EQ(b.samples.size(),
            static_cast<std::size_t>(std::floor(b.end_time / kSampleInterval)));
  for (std::size_t k = 0; k < b.samples.size(); ++k)
    EXPECT_DOUBLE_EQ(b.samples[k].time, static_cast<double>(k + 1) * kSampleInterval);
  // The CSV holds both kinds of rows, in time order.
  const std::string csv = TraceCsv(b);
  EXPECT_EQ(csv.rfind("row,t,", 0), 0u);
  EXPECT_NE(csv.find("\nsample,0.0005"), std::string::npos);
  EXPECT_NE(csv.find("\ndecision,0.1"), std::string::npos);
  EXPECT_LT(csv.find("\nsample,0.0995"), csv.find("\ndecision,0.1"));
  EXPECT_LT(csv.find("\ndecision,0.1"), csv.find("\nsample,0.1005"));
}

// CPodes stops its steps at any report time it is given: samples are
// interpolated between accepted steps instead, so they change nothing here
// either (the resolved peg scene, integrated by CPodes, its reference), nor
// under the scene's own CVODE.
TEST(TrialHealth, SamplesDoNotChangeAStiffTrajectory) {
  scene::Scene s = LoadExample("peg_in_hole.json");
  ASSERT_EQ(s.params.simulation.integrator, "CVODE");
  EXPECT_GT(RunBoth(s, false).b.samples.size(), 200u);
  s.params.simulation.integrator = "CPodes";
  EXPECT_GT(RunBoth(s, false).b.samples.size(), 200u);
}

// Timing where the time goes (TrialOptions::time_phases, for the
// benchmarks) changes no bit; under CVODE it finds time in each phase, under
// Simbody's steppers none in the Jacobians and linear algebra (Simbody's
// own).
TEST(TrialHealth, TimingThePhasesChangesNoBit) {
  for (const char* integrator : {"CVODE", "RungeKuttaMerson"}) {
    SCOPED_TRACE(integrator);
    scene::Scene s = LoadExample("peg_in_hole_shell.json");
    s.params.simulation.integrator = integrator;
    TrialOptions plain, timed;
    plain.record_trace = timed.record_trace = false;
    timed.time_phases = true;
    const TrialResult a = RunTrial(s, {1, 0}, plain), b = RunTrial(s, {1, 0}, timed);
    ASSERT_EQ(a.status, Status::kCompleted) << a.detail;
    EXPECT_EQ(a.completion_time, b.completion_time);
    EXPECT_EQ(a.counters.steps_taken, b.counters.steps_taken);
    EXPECT_EQ(a.final_row.position, b.final_row.position);
    EXPECT_EQ(a.phases.contact + a.phases.jacobian + a.phases.linear_algebra +
                  a.phases.hand + a.phases.decisions + a.phases.visibility,
              0.0);
    EXPECT_GT(b.phases.contact, 0.0);
    EXPECT_GT(b.phases.hand, 0.0);
    EXPECT_GT(b.phases.visibility, 0.0);  // the scene casts V
    EXPECT_GT(b.phases.decisions, 0.0);
    EXPECT_LT(b.phases.contact + b.phases.jacobian + b.phases.linear_algebra +
                  b.phases.hand + b.phases.decisions + b.phases.visibility,
              b.wall_seconds);
    if (s.params.simulation.integrator == "CVODE") {
      EXPECT_GT(b.phases.jacobian, 0.0);
      EXPECT_GT(b.phases.linear_algebra, 0.0);
    } else {
      EXPECT_EQ(b.phases.jacobian, 0.0);
      EXPECT_EQ(b.phases.linear_algebra, 0.0);
    }
  }
}

TEST(TrialHealth, TooSoftAContactIsAPenetrationWarning) {
  scene::Scene s = LoadExample("peg_in_hole_shell.json");
  s.params.contact.stiffness = 1e7;  // Pa/m: a thousand times too soft for the fit
  const TrialResult r = RunTrial(s, {1, 0}, {0, 0.0, false});
  EXPECT_NEAR(r.clearance, 50e-6, 1e-12);
  EXPECT_NEAR(r.penetration_bound, 5e-6, 1e-12);  // 0.1 of the clearance
  EXPECT_GT(r.max_penetration, r.penetration_bound);
  const WarningEntry& w = r.warnings.at(WarningKind::kPenetrationBound);
  EXPECT_GT(w.count, 0);
  EXPECT_GT(w.first_time, 0.0);
  EXPECT_NE(w.detail.find("radial clearance"), std::string::npos) << w.detail;
  EXPECT_NE(r.BriefReport().find("penetration_bound"), std::string::npos);
}

TEST(TrialHealth, AFreeMoveHasNoWarningAndNoBound) {
  const TrialResult r = RunTrial(LoadExample("free_move.json"), {1, 0});
  EXPECT_EQ(r.status, Status::kCompleted) << r.detail;
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.Summary();
  EXPECT_EQ(r.penetration_bound, 0.0);  // nothing fixed: no fit to bound
  EXPECT_EQ(r.max_penetration, 0.0);
}

TEST(TrialHealth, AnEndingAtTheFirstDecisionReadsNoIntegratorCounters) {
  scene::Scene s = LoadExample("free_move.json");
  s.op.position = {0.0, -3.0};  // out of reach at the first decision
  // Every stepper: Simbody's integrators and CVODE (cvode_stepper.cc) end
  // the trial on different paths.
  for (const std::string& integrator : scene::StepperNames()) {
    SCOPED_TRACE(integrator);
    s.params.simulation.integrator = integrator;
    const TrialResult r = RunTrial(s, {1, 0});
    ASSERT_EQ(r.status, Status::kUnreachable);
    EXPECT_EQ(r.counters.steps_taken, 0);
    EXPECT_EQ(r.counters.steps_attempted, 0);
    EXPECT_EQ(r.counters.error_test_failures, 0);
    EXPECT_EQ(r.counters.realizations, 0);
    EXPECT_EQ(r.counters.jacobian_evaluations, 0);
    EXPECT_EQ(r.counters.convergence_failures, 0);
    EXPECT_EQ(r.counters.decisions, 1);
    EXPECT_NE(r.BriefReport().find(": 0 steps taken, 0 attempted, 0 error-test failures, "
                                   "0 realizations\n"),
              std::string::npos)
        << r.BriefReport();
  }
}

}  // namespace
}  // namespace vahf::sim
