// Spatially resolved transport (core/spatial/, docs/model.md §21), one thread; part of bench_core.
//   Run: cmake --build build --target bench && build/tests/bench/bench_core --benchmark_filter=Lateral\|Profile
// Issue 43's targets are 50 ms for one channel's profile at 256 radii and 1.5 s for a 31-wavelength skin; these are
// the numbers that work stands at (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <vector>

#include "app/material/material_document.h"
#include "app/process/parallel_for.h"
#include "app/solution/document_profile.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/skin/skin_optics.h"
#include "core/spatial/lateral_frequency_response.h"
#include "core/spatial/layer_profile.h"

namespace skinlayer::bench {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One spatial frequency of a half-space (Omega 0.99, g 0.8, k 1 / mfp). Args: ordinates, azimuthal modes.
void BM_LateralFrequencyResponse(benchmark::State& state) {
  const LateralFrequencyResolution resolution{static_cast<int>(state.range(0)), static_cast<int>(state.range(1))};
  for (auto _ : state) {
    benchmark::DoNotOptimize(open_layer_lateral_response(kInf, 0.99, 0.8, 1.0, resolution));
  }
}
BENCHMARK(BM_LateralFrequencyResponse)->Args({12, 16})->Args({16, 24})->Args({24, 40})->Unit(benchmark::kMillisecond);

// Its single scattering, solved without the scattering operator (one small eigen-solve per node).
void BM_LateralSingleScattering(benchmark::State& state) {
  const LateralFrequencyResolution resolution{static_cast<int>(state.range(0)), static_cast<int>(state.range(1))};
  for (auto _ : state) {
    benchmark::DoNotOptimize(open_layer_single_scattering_response(kInf, 0.99, 0.8, 1.0, resolution));
  }
}
BENCHMARK(BM_LateralSingleScattering)->Args({12, 16})->Args({16, 24})->Unit(benchmark::kMillisecond);

// The half-space profile of tests/core/spatial/layer_profile_test.cpp: 15 annuli out to 24 mfp, 40 frequencies.
void BM_LayerProfile(benchmark::State& state) {
  const std::vector<double> edges = {0.0, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0,  1.5,
                                     2.0, 3.0, 4.0, 6.0,  8.0, 12.0, 16.0, 24.0};
  LayerProfileOptions options;
  options.resolution = {static_cast<int>(state.range(0)), static_cast<int>(state.range(1))};
  options.frequencies = 40;
  for (auto _ : state) benchmark::DoNotOptimize(layer_profile({kInf, 0.99, 0.8}, edges, options));
}
BENCHMARK(BM_LayerProfile)->Args({12, 16})->Args({16, 24})->Unit(benchmark::kMillisecond);

// One wavelength of the default skin (550 nm: a 60 um epidermis over the dermis, sigma 0.5 top) at 256 radii from
// 0.01 to 5 mm, at 12 nodes and 16 modes (the command's resolution). Arg: the number of spatial frequencies.
void BM_SkinWavelengthProfile(benchmark::State& state) {
  const Material m = skin_material(SkinParameters{}, 550.0);
  ProfileLayer layer{m.tau, m.albedo, m.g};
  layer.top = top_interface(m);
  layer.below = {LateralSlab{kInf, m.below[0].albedo, m.below[0].g, *m.below[0].extinction / *m.extinction}};
  std::vector<double> radii;
  for (int i = 0; i < 256; ++i) radii.push_back(*m.extinction * 0.01 * std::pow(500.0, i / 255.0));
  LayerProfileOptions options;
  options.resolution = {12, 16};
  options.frequencies = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(layer_profile_at(layer, radii, options));
}
BENCHMARK(BM_SkinWavelengthProfile)->Arg(16)->Arg(24)->Arg(40)->Iterations(1)->Unit(benchmark::kMillisecond);

// The whole default skin as `skinlayer profile --skin` computes it: 31 wavelengths at 256 radii from 0.01 to 5 mm,
// on both cores through the executables' parallel-for (issue 43's target: 1.5 s).
void BM_SkinProfile(benchmark::State& state) {
  MaterialDocument document;
  document.skin = SkinParameters{};
  std::vector<double> radii;
  for (int i = 0; i < 256; ++i) radii.push_back(0.01 * std::pow(500.0, i / 255.0));
  ProfileRequest request;
  request.options.parallel_for = parallel_for_threads;
  for (auto _ : state) benchmark::DoNotOptimize(document_profile_at_radii(document, radii, request));
}
BENCHMARK(BM_SkinProfile)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);

// A finite slab (tau 1, Omega 0.9, g 0.8) under a sigma 0.3 top, both faces in 15 annuli, on the 24 nodes its
// transmittance takes (docs/model.md §21.15), one thread.
void BM_FiniteSlabProfile(benchmark::State& state) {
  ProfileLayer layer{1.0, 0.9, 0.8};
  layer.top = RoughDielectric{1.4, 0.3};
  const std::vector<double> edges = {0.0, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.6, 0.8, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0};
  LayerProfileOptions options;
  options.resolution = {24, 16};
  options.frequencies = 40;
  for (auto _ : state) benchmark::DoNotOptimize(layer_profile(layer, edges, options));
}
BENCHMARK(BM_FiniteSlabProfile)->Iterations(1)->Unit(benchmark::kMillisecond);

// The paper's layer between two rough interfaces (tau 1.6, sigma 0.5 and eta 1.4 on both faces, Omega 0.95, g 0.8),
// both faces in 15 annuli on 24 nodes, with the bounce's finer image (docs/model.md §21.17), one thread.
void BM_RoughBottomProfile(benchmark::State& state) {
  Material m;
  m.albedo = 0.95;
  const std::vector<double> edges = {0.0, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0};
  LayerProfileOptions options;
  options.resolution = {24, 16};
  options.frequencies = 40;
  for (auto _ : state) benchmark::DoNotOptimize(layer_profile(profile_layer(m), edges, options));
}
BENCHMARK(BM_RoughBottomProfile)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace skinlayer::bench
