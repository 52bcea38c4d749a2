#include "vahf/experiment/result_codec.h"

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <vector>

#include "vahf/core/error.h"

namespace vahf::experiment {
namespace {

using nlohmann::json;

// A codec that forgets a field would resume a run with that field at its
// default: each struct's size pins its fields, so that adding one without
// adding it here fails to compile (the sizes of libstdc++ on x86-64, the
// only target; docs/design.md, "Layout and dependencies").
static_assert(sizeof(sim::TrialCounters) == 14 * 8, "encode the new counter");
static_assert(sizeof(human::FactorValues) == 9 * 8, "encode the new factor");
static_assert(sizeof(sim::PhaseSeconds) == 6 * 8, "encode the new phase");
static_assert(sizeof(sim::TraceRow) == 288, "encode the new field of TraceRow");
static_assert(sizeof(sim::RestSummary) == 4 * 8, "encode the new field of RestSummary");
static_assert(sizeof(sim::TrialResult) == 1088, "encode the new field of TrialResult");
static_assert(sizeof(Warnings) == 7 * 48, "encode the new field of Warnings");
static_assert(sizeof(PartRun) == 1104, "encode the new field of PartRun");
static_assert(sizeof(CycleResult) == 392, "encode the new field of CycleResult");
static_assert(sizeof(CycleRecord) == 432, "encode the new field of CycleRecord");
static_assert(sizeof(StabilityTrial) == 1152, "encode the new field of StabilityTrial");

[[noreturn]] void NotAnEncoding(const std::string& why) {
  throw ComputationError(ComputationError::Reason::kRefused,
                         "journal entry: not an encoded result: " + why);
}

std::uint64_t Bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

double FromBits(const json& j) {
  const std::uint64_t b = j.get<std::uint64_t>();
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

template <class Vector>
void Put(json& out, const Vector& v) {
  for (int k = 0; k < v.size(); ++k) out.push_back(Bits(v[k]));
}

// A trace row as one array of bit patterns, in declaration order.
json RowToJson(const sim::TraceRow& r) {
  json out = json::array({Bits(r.time)});
  Put(out, r.position);
  Put(out, r.orientation.coeffs());  // x, y, z, w
  for (const Eigen::Vector3d* v : {&r.velocity, &r.angular_velocity, &r.assembly_force,
                                   &r.contact_force, &r.friction_force})
    Put(out, *v);
  const human::FactorValues& f = r.factors;
  for (double x : {f.V, f.sight_angle_deg, f.f, f.eta, f.shoulder_distance, f.r,
                   f.glance_angle_deg, f.g, f.lambda_c, r.work, r.psi, r.penetration})
    out.push_back(Bits(x));
  return out;
}

sim::TraceRow RowFromJson(const json& j) {
  std::size_t k = 0;
  const auto next = [&] { return FromBits(j.at(k++)); };
  const auto vector = [&](Eigen::Vector3d* v) {
    for (int i = 0; i < 3; ++i) (*v)[i] = next();
  };
  sim::TraceRow r;
  r.time = next();
  vector(&r.position);
  for (int i = 0; i < 4; ++i) r.orientation.coeffs()[i] = next();
  for (Eigen::Vector3d* v : {&r.velocity, &r.angular_velocity, &r.assembly_force,
                             &r.contact_force, &r.friction_force})
    vector(v);
  human::FactorValues& f = r.factors;
  for (double* x :
       {&f.V, &f.sight_angle_deg, &f.f, &f.eta, &f.shoulder_distance, &f.r,
        &f.glance_angle_deg, &f.g, &f.lambda_c, &r.work, &r.psi, &r.penetration})
    *x = next();
  if (k != j.size()) NotAnEncoding("a trace row too long");
  return r;
}

json RowsToJson(const std::vector<sim::TraceRow>& rows) {
  json out = json::array();
  for (const sim::TraceRow& r : rows) out.push_back(RowToJson(r));
  return out;
}

std::vector<sim::TraceRow> RowsFromJson(const json& j) {
  std::vector<sim::TraceRow> rows;
  for (const json& r : j) rows.push_back(RowFromJson(r));
  return rows;
}

json WarningsToJson(const Warnings& w) {
  json out = json::array();
  for (int k = 0; k < kWarningKinds; ++k) {
    const WarningEntry& e = w.at(static_cast<WarningKind>(k));
    out.push_back({e.count, Bits(e.first_time), e.detail});
  }
  return out;
}

Warnings WarningsFromJson(const json& j) {
  Warnings w;
  for (int k = 0; k < kWarningKinds; ++k) {
    const json& e = j.at(k);
    w.Note(static_cast<WarningKind>(k), FromBits(e.at(1)), e.at(2).get<std::string>(),
           e.at(0).get<std::int64_t>());
  }
  return w;
}

// The counters in declaration order.
std::vector<std::int64_t*> Counters(sim::TrialCounters& c) {
  return {&c.decisions,
          &c.steps_taken,
          &c.steps_attempted,
          &c.error_test_failures,
          &c.realizations,
          &c.jacobian_evaluations,
          &c.convergence_failures,
          &c.contact_evaluations,
          &c.contact_point_queries,
          &c.contact_tests,
          &c.broad_phase_skips,
          &c.clusters_skipped,
          &c.rays_cast,
          &c.shell_points};
}

std::vector<double*> Phases(sim::PhaseSeconds& p) {
  return {&p.contact, &p.jacobian,  &p.linear_algebra,
          &p.hand,    &p.decisions, &p.visibility};
}

// The doubles of a trial result, in declaration order.
std::vector<double*> Numbers(sim::TrialResult& t) {
  return {&t.end_time,  &t.completion_time, &t.first_contact_time,
          &t.accuracy,  &t.wall_seconds,    &t.cpu_seconds,
          &t.work,      &t.max_penetration, &t.penetration_bound,
          &t.clearance, &t.stiffness,       &t.line_stiffness};
}

json TrialToJson(const sim::TrialResult& trial) {
  sim::TrialResult& t = const_cast<sim::TrialResult&>(trial);  // read only
  json numbers = json::array(), counters = json::array(), phases = json::array();
  for (double* x : Numbers(t)) numbers.push_back(Bits(*x));
  for (std::int64_t* c : Counters(t.counters)) counters.push_back(*c);
  for (double* x : Phases(t.phases)) phases.push_back(Bits(*x));
  return {{"status", static_cast<int>(t.status)},
          {"detail", t.detail},
          {"part", t.part},
          {"integrator", t.integrator},
          {"key", {t.key.seed, t.key.trial}},
          {"numbers", numbers},
          {"counters", counters},
          {"phases", phases},
          {"trace", RowsToJson(t.trace)},
          {"samples", RowsToJson(t.samples)},
          {"warnings", WarningsToJson(t.warnings)},
          {"rests",
           {t.rests.count, Bits(t.rests.total_time), Bits(t.rests.longest),
            t.rests.withdrawals}},
          {"final_row", RowToJson(t.final_row)}};
}

sim::TrialResult TrialFromJson(const json& j) {
  sim::TrialResult t;
  const int status = j.at("status").get<int>();
  if (status < 0 || status > static_cast<int>(sim::Status::kStepBudget))
    NotAnEncoding("an unknown status");
  t.status = static_cast<sim::Status>(status);
  t.detail = j.at("detail").get<std::string>();
  t.part = j.at("part").get<std::string>();
  t.integrator = j.at("integrator").get<std::string>();
  t.key = {j.at("key").at(0).get<std::uint64_t>(),
           j.at("key").at(1).get<std::uint64_t>()};
  const auto fill = [](const json& from, const auto& into, auto read) {
    if (from.size() != into.size()) NotAnEncoding("a wrong number of fields");
    for (std::size_t k = 0; k < into.size(); ++k) *into[k] = read(from.at(k));
  };
  fill(j.at("numbers"), Numbers(t), FromBits);
  fill(j.at("counters"), Counters(t.counters),
       [](const json& c) { return c.get<std::int64_t>(); });
  fill(j.at("phases"), Phases(t.phases), FromBits);
  t.trace = RowsFromJson(j.at("trace"));
  t.samples = RowsFromJson(j.at("samples"));
  t.warnings = WarningsFromJson(j.at("warnings"));
  const json& rests = j.at("rests");
  t.rests = {rests.at(0).get<std::int64_t>(), FromBits(rests.at(1)),
             FromBits(rests.at(2)), rests.at(3).get<std::int64_t>()};
  t.final_row = RowFromJson(j.at("final_row"));
  return t;
}

json CycleToJson(const CycleResult& c) {
  json parts = json::array();
  for (const PartRun& p : c.parts)
    parts.push_back({{"trial", TrialToJson(p.trial)},
                     {"start", {Bits(p.start_time), Bits(p.start_work)}}});
  return {{"parts", parts},
          {"completed", c.completed},
          {"numerical_failure", c.numerical_failure},
          {"time", Bits(c.time)},
          {"work", Bits(c.work)},
          {"warnings", WarningsToJson(c.warnings)}};
}

CycleResult CycleFromJson(const json& j) {
  CycleResult c;
  for (const json& p : j.at("parts"))
    c.parts.push_back({TrialFromJson(p.at("trial")), FromBits(p.at("start").at(0)),
                       FromBits(p.at("start").at(1))});
  c.completed = j.at("completed").get<bool>();
  c.numerical_failure = j.at("numerical_failure").get<bool>();
  c.time = FromBits(j.at("time"));
  c.work = FromBits(j.at("work"));
  c.warnings = WarningsFromJson(j.at("warnings"));
  return c;
}

std::string ToBytes(const json& j) {
  const std::vector<std::uint8_t> cbor = json::to_cbor(j);
  return std::string(cbor.begin(), cbor.end());
}

// Parses and converts, turning the library's errors into one of ours.
template <class Convert>
auto FromBytes(const std::string& bytes, const char* what, Convert convert) {
  try {
    return convert(json::from_cbor(bytes));
  } catch (const json::exception& e) {
    throw ComputationError(
        ComputationError::Reason::kRefused,
        std::string("journal entry: not an encoded ") + what + ": " + e.what());
  }
}

}  // namespace

std::string EncodeCycleRecord(const CycleRecord& r) {
  return ToBytes({{"condition", r.condition},
                  {"cycle", r.cycle},
                  {"start_minute", Bits(r.start_minute)},
                  {"initial_work", Bits(r.initial_work)},
                  {"repetition", r.repetition},
                  {"result", CycleToJson(r.result)}});
}

CycleRecord DecodeCycleRecord(const std::string& bytes) {
  return FromBytes(bytes, "cycle", [](const json& j) {
    CycleRecord r;
    r.condition = j.at("condition").get<std::size_t>();
    r.cycle = j.at("cycle").get<std::uint64_t>();
    r.start_minute = FromBits(j.at("start_minute"));
    r.initial_work = FromBits(j.at("initial_work"));
    r.repetition = j.at("repetition").get<int>();
    r.result = CycleFromJson(j.at("result"));
    return r;
  });
}

std::string EncodeStabilityTrial(const StabilityTrial& t) {
  return ToBytes({{"case", t.case_index},
                  {"integrator", t.integrator_index},
                  {"seed", t.seed_index},
                  {"result", TrialToJson(t.result)},
                  {"failures", t.failures}});
}

StabilityTrial DecodeStabilityTrial(const std::string& bytes) {
  return FromBytes(bytes, "stability trial", [](const json& j) {
    StabilityTrial t;
    t.case_index = j.at("case").get<std::size_t>();
    t.integrator_index = j.at("integrator").get<std::size_t>();
    t.seed_index = j.at("seed").get<int>();
    t.result = TrialFromJson(j.at("result"));
    t.failures = j.at("failures").get<std::vector<std::string>>();
    return t;
  });
}

}  // namespace vahf::experiment
