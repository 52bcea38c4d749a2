// Speed of the contact point queries SignedDistance::Penetration and ::At on
// the barrel of experiments/scenes/hydraulic_cylinder.json, at 4096 fixed points
// near its bore wall: radius within 50 micrometres of the bore's 31.5115 mm,
// z along the bore. There the piston rod's shell points sit during insertion,
// and these queries dominate a trial. Run with tools/bench.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "vahf/contact/signed_distance.h"
#include "vahf/scene/scene_loader.h"

namespace {

const vahf::geometry::Shape& Barrel() {
  static const vahf::scene::Scene scene = vahf::scene::LoadScene(
      std::string(VAHF_SOURCE_DIR) + "/experiments/scenes/hydraulic_cylinder.json");
  for (const vahf::scene::Part& p : scene.parts)
    if (p.name == "barrel") return p.shape;
  std::abort();
}

std::vector<Eigen::Vector3d> NearTheBoreWall() {
  constexpr double kBore = 0.0315115, kBand = 50e-6;  // m
  std::mt19937_64 gen(20240607);
  std::uniform_real_distribution<double> radius(kBore - kBand, kBore + kBand),
      azimuth(0.0, 2 * M_PI), height(0.01, 0.299);
  std::vector<Eigen::Vector3d> points(4096);
  for (Eigen::Vector3d& p : points) {
    const double r = radius(gen), phi = azimuth(gen);
    p = {r * std::cos(phi), r * std::sin(phi), height(gen)};
  }
  return points;
}

void Penetration(benchmark::State& state) {
  const vahf::contact::SignedDistance f(Barrel());
  const std::vector<Eigen::Vector3d> points = NearTheBoreWall();
  std::int64_t inside = 0;
  for (auto _ : state) {
    for (const Eigen::Vector3d& p : points) {
      const auto d = f.Penetration(p);
      inside += d.has_value();
      benchmark::DoNotOptimize(d);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
  state.counters["inside"] =
      benchmark::Counter(static_cast<double>(inside), benchmark::Counter::kAvgIterations);
}

void At(benchmark::State& state) {
  const vahf::contact::SignedDistance f(Barrel());
  const std::vector<Eigen::Vector3d> points = NearTheBoreWall();
  for (auto _ : state) {
    for (const Eigen::Vector3d& p : points) benchmark::DoNotOptimize(f.At(p));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
}

BENCHMARK(Penetration)->Unit(benchmark::kMicrosecond);
BENCHMARK(At)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
