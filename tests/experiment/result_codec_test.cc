// The journal's codec: a real cycle of the hydraulic cylinder with its traces,
// and a stability trial, decode to the same bits (re-encoded: the same
// bytes; every double compared as bits, so NaN's sign and -0.0 count);
// bytes that are not an encoding are a ComputationError.
#include "vahf/experiment/result_codec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include "vahf/core/error.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::experiment {
namespace {

std::string Source(const std::string& relative) {
  const char* root = std::getenv("VAHF_SOURCE_DIR");
  return std::string(root ? root : VAHF_SOURCE_DIR) + "/" + relative;
}

std::uint64_t Bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

void ExpectSameRow(const sim::TraceRow& a, const sim::TraceRow& b) {
  EXPECT_EQ(Bits(a.time), Bits(b.time));
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(Bits(a.position[k]), Bits(b.position[k]));
    EXPECT_EQ(Bits(a.velocity[k]), Bits(b.velocity[k]));
    EXPECT_EQ(Bits(a.angular_velocity[k]), Bits(b.angular_velocity[k]));
    EXPECT_EQ(Bits(a.assembly_force[k]), Bits(b.assembly_force[k]));
    EXPECT_EQ(Bits(a.contact_force[k]), Bits(b.contact_force[k]));
    EXPECT_EQ(Bits(a.friction_force[k]), Bits(b.friction_force[k]));
  }
  for (int k = 0; k < 4; ++k)
    EXPECT_EQ(Bits(a.orientation.coeffs()[k]), Bits(b.orientation.coeffs()[k]));
  EXPECT_EQ(Bits(a.factors.eta), Bits(b.factors.eta));
  EXPECT_EQ(Bits(a.factors.lambda_c), Bits(b.factors.lambda_c));
  EXPECT_EQ(Bits(a.factors.glance_angle_deg), Bits(b.factors.glance_angle_deg));
  EXPECT_EQ(Bits(a.work), Bits(b.work));
  EXPECT_EQ(Bits(a.psi), Bits(b.psi));
  EXPECT_EQ(Bits(a.penetration), Bits(b.penetration));
}

void ExpectSameTrial(const sim::TrialResult& a, const sim::TrialResult& b) {
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.detail, b.detail);
  EXPECT_EQ(a.part, b.part);
  EXPECT_EQ(a.integrator, b.integrator);
  EXPECT_EQ(a.key.seed, b.key.seed);
  EXPECT_EQ(a.key.trial, b.key.trial);
  EXPECT_EQ(Bits(a.end_time), Bits(b.end_time));
  EXPECT_EQ(Bits(a.completion_time), Bits(b.completion_time));
  EXPECT_EQ(Bits(a.first_contact_time), Bits(b.first_contact_time));
  EXPECT_EQ(Bits(a.work), Bits(b.work));
  EXPECT_EQ(Bits(a.max_penetration), Bits(b.max_penetration));
  EXPECT_EQ(Bits(a.stiffness), Bits(b.stiffness));
  EXPECT_EQ(Bits(a.cpu_seconds), Bits(b.cpu_seconds));
  EXPECT_EQ(a.counters.steps_taken, b.counters.steps_taken);
  EXPECT_EQ(a.counters.rays_cast, b.counters.rays_cast);
  EXPECT_EQ(a.counters.shell_points, b.counters.shell_points);
  EXPECT_EQ(Bits(a.phases.visibility), Bits(b.phases.visibility));
  EXPECT_EQ(a.warnings.Summary(), b.warnings.Summary());
  EXPECT_EQ(a.rests.count, b.rests.count);
  EXPECT_EQ(Bits(a.rests.total_time), Bits(b.rests.total_time));
  EXPECT_EQ(Bits(a.rests.longest), Bits(b.rests.longest));
  ASSERT_EQ(a.trace.size(), b.trace.size());
  for (std::size_t k = 0; k < a.trace.size(); ++k) ExpectSameRow(a.trace[k], b.trace[k]);
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (std::size_t k = 0; k < a.samples.size(); ++k)
    ExpectSameRow(a.samples[k], b.samples[k]);
  ExpectSameRow(a.final_row, b.final_row);
}

TEST(ResultCodec, ACycleOfTheCylinderDecodesToTheSameBits) {
  const scene::Scene s =
      scene::LoadScene(Source("experiments/scenes/hydraulic_cylinder.json"));
  CycleRecord r;
  r.condition = 2;
  r.cycle = 17;
  r.start_minute = 12.5;
  r.initial_work = 1234.5;
  r.repetition = 3;
  r.result = RunCycle(s, 1, 0, r.initial_work, true);
  ASSERT_FALSE(r.result.parts.empty());
  ASSERT_FALSE(r.result.parts[0].trial.trace.empty());
  // What a run never gives but a result may hold: NaN of either sign, -0.0,
  // samples, a warning, rests.
  sim::TrialResult& t = r.result.parts[0].trial;
  t.first_contact_time = -std::numeric_limits<double>::quiet_NaN();
  t.clearance = -0.0;
  t.samples = {t.trace.front(), t.trace.back()};
  t.samples[1].psi = std::numeric_limits<double>::quiet_NaN();
  t.warnings.Note(WarningKind::kNonFiniteState, 0.25, "NaN in\nthe state", 7);
  t.rests = {3, 1.25, -0.0};  // not what a run gives: each field its own bits

  const std::string bytes = EncodeCycleRecord(r);
  const CycleRecord d = DecodeCycleRecord(bytes);
  EXPECT_EQ(EncodeCycleRecord(d), bytes);
  EXPECT_EQ(d.condition, 2u);
  EXPECT_EQ(d.cycle, 17u);
  EXPECT_EQ(Bits(d.start_minute), Bits(12.5));
  EXPECT_EQ(Bits(d.initial_work), Bits(1234.5));
  EXPECT_EQ(d.repetition, 3);
  EXPECT_EQ(d.result.completed, r.result.completed);
  EXPECT_EQ(d.result.numerical_failure, r.result.numerical_failure);
  EXPECT_EQ(Bits(d.result.time), Bits(r.result.time));
  EXPECT_EQ(Bits(d.result.work), Bits(r.result.work));
  EXPECT_EQ(d.result.warnings.Summary(), r.result.warnings.Summary());
  ASSERT_EQ(d.result.parts.size(), r.result.parts.size());
  for (std::size_t p = 0; p < d.result.parts.size(); ++p) {
    EXPECT_EQ(Bits(d.result.parts[p].start_time), Bits(r.result.parts[p].start_time));
    EXPECT_EQ(Bits(d.result.parts[p].start_work), Bits(r.result.parts[p].start_work));
    ExpectSameTrial(d.result.parts[p].trial, r.result.parts[p].trial);
  }
  const sim::TrialResult& dt = d.result.parts[0].trial;
  EXPECT_TRUE(std::isnan(dt.first_contact_time) && std::signbit(dt.first_contact_time));
  EXPECT_TRUE(dt.clearance == 0 && std::signbit(dt.clearance));
  EXPECT_EQ(dt.rests.count, 3);
  EXPECT_EQ(Bits(dt.rests.total_time), Bits(1.25));
  EXPECT_TRUE(dt.rests.longest == 0 && std::signbit(dt.rests.longest));
  for (int k = 0; k < kWarningKinds; ++k) {
    const WarningEntry& a = dt.warnings.at(static_cast<WarningKind>(k));
    const WarningEntry& b = t.warnings.at(static_cast<WarningKind>(k));
    EXPECT_EQ(a.count, b.count);
    EXPECT_EQ(Bits(a.first_time), Bits(b.first_time));
    EXPECT_EQ(a.detail, b.detail);
  }
  EXPECT_EQ(dt.warnings.at(WarningKind::kNonFiniteState).detail, "NaN in\nthe state");
}

TEST(ResultCodec, AStabilityTrialDecodesToTheSameBits) {
  StabilityTrial t;
  t.case_index = 4;
  t.integrator_index = 1;
  t.seed_index = 9;
  t.result.status = sim::Status::kStepBudget;
  t.result.detail = "budget\nspent";
  t.result.end_time = 0.1 + 0.2;
  t.result.counters.contact_tests = 1LL << 40;
  t.failures = {"ended step_budget", "a second reason"};
  const StabilityTrial d = DecodeStabilityTrial(EncodeStabilityTrial(t));
  EXPECT_EQ(d.case_index, 4u);
  EXPECT_EQ(d.integrator_index, 1u);
  EXPECT_EQ(d.seed_index, 9);
  EXPECT_EQ(d.failures, t.failures);
  ExpectSameTrial(d.result, t.result);
  EXPECT_EQ(d.result.counters.contact_tests, 1LL << 40);
}

TEST(ResultCodec, BytesThatAreNoEncodingAreRefused) {
  for (const std::string& bytes :
       {std::string(), std::string("not cbor"), EncodeStabilityTrial(StabilityTrial{})}) {
    try {
      DecodeCycleRecord(bytes);
      ADD_FAILURE() << "decoded";
    } catch (const ComputationError& e) {
      EXPECT_EQ(e.reason(), ComputationError::Reason::kRefused);
      EXPECT_NE(std::string(e.what()).find("journal entry: not an encoded "),
                std::string::npos);
    }
  }
}

}  // namespace
}  // namespace vahf::experiment
