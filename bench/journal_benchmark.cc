// What journaling costs a run (experiment/journal.h, docs/reproducibility.md
// "Resume"): each finished cycle is encoded (result_codec.h) and appended to
// its batch's file, and a resumed cycle is decoded instead of run. Measured
// on a real cycle of the hydraulic cylinder (seed 1, cycle 0, with its
// decision traces, as table1 and the working conditions record them), whose
// own cost is CycleCost's. Run with tools/bench.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "vahf/experiment/cycle.h"
#include "vahf/experiment/journal.h"
#include "vahf/experiment/result_codec.h"
#include "vahf/scene/scene_loader.h"

namespace {

using vahf::experiment::CycleRecord;

const CycleRecord& Cycle() {
  static const CycleRecord record = [] {
    CycleRecord r;
    r.result = vahf::experiment::RunCycle(
        vahf::scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                               "/experiments/scenes/hydraulic_cylinder.json"),
        1, 0, 0.0, true);
    return r;
  }();
  return record;
}

// The cycle itself, for scale.
void CycleCost(benchmark::State& state) {
  const vahf::scene::Scene scene = vahf::scene::LoadScene(
      std::string(VAHF_SOURCE_DIR) + "/experiments/scenes/hydraulic_cylinder.json");
  const auto models = vahf::sim::BuildSequenceModels(scene);
  for (auto _ : state)
    benchmark::DoNotOptimize(vahf::experiment::RunCycle(models, 1, 0, 0.0, true).time);
}
BENCHMARK(CycleCost)->Unit(benchmark::kMillisecond);

void Encode(benchmark::State& state) {
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string b = vahf::experiment::EncodeCycleRecord(Cycle());
    bytes = b.size();
    benchmark::DoNotOptimize(b.data());
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(Encode)->Unit(benchmark::kMicrosecond);

void Decode(benchmark::State& state) {
  const std::string bytes = vahf::experiment::EncodeCycleRecord(Cycle());
  for (auto _ : state)
    benchmark::DoNotOptimize(vahf::experiment::DecodeCycleRecord(bytes).result.time);
}
BENCHMARK(Decode)->Unit(benchmark::kMicrosecond);

// Encoding and appending one record, as a finished cycle is journaled.
void EncodeAndStore(benchmark::State& state) {
  const std::string dir =
      (std::filesystem::temp_directory_path() / "vahf_journal_benchmark").string();
  {
    vahf::experiment::Journal journal(dir, {{"benchmark", 1}}, false);
    const auto batch = journal.Begin(1u << 30, "benchmark");
    std::size_t i = 0;
    for (auto _ : state) batch->Store(i++, vahf::experiment::EncodeCycleRecord(Cycle()));
  }
  std::filesystem::remove_all(dir);
}
BENCHMARK(EncodeAndStore)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
