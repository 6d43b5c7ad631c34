// Solver speed, one channel, one thread. Run: cmake --build build --target bench && build/tests/bench/bench_core
#include <benchmark/benchmark.h>

#include "core/solver.h"

namespace {

// A full single-channel solve at the paper's default (sigma 0.5, eta 1.4, T 0.2, Omega 1, g 0.8, bottom air) at the
// automatic resolution, which tests/core/solver_limits_test.cpp checks is converged to 0.5% in the BRDF.
void BM_SolveDefault(benchmark::State& state) {
  const skinlayer::Material material;
  for (auto _ : state) {
    skinlayer::LayerTables tables = skinlayer::solve(material);
    benchmark::DoNotOptimize(tables);
  }
  state.counters["ordinates"] = skinlayer::choose_resolution(material).ordinates;
  state.counters["modes"] = skinlayer::solve(material).modes();
}
BENCHMARK(BM_SolveDefault)->Unit(benchmark::kMillisecond);

// The same solve at a fixed number of ordinates per hemisphere.
void BM_SolveOrdinates(benchmark::State& state) {
  skinlayer::Material material;
  material.ordinates = static_cast<int>(state.range(0));
  for (auto _ : state) {
    skinlayer::LayerTables tables = skinlayer::solve(material);
    benchmark::DoNotOptimize(tables);
  }
}
BENCHMARK(BM_SolveOrdinates)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);

// Directional albedo at four incident angles (what `skinlayer albedo` computes).
void BM_DirectionalAlbedo(benchmark::State& state) {
  const skinlayer::Material material;
  const std::vector<double> theta = {0.0, 0.5236, 1.0472, 1.3963};
  for (auto _ : state) benchmark::DoNotOptimize(skinlayer::directional_albedo(material, theta));
}
BENCHMARK(BM_DirectionalAlbedo)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
