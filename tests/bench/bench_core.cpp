// Solver speed, one channel, one thread, and the Monte Carlo reference for comparison.
//   Run:        cmake --build build --target bench && build/tests/bench/bench_core
//   Report:     cmake --build build --target benchmarks-doc   (runs bench_core --report docs/benchmarks.md: every
//               benchmark below, a power-law fit of the solve time in N with its plot, the per-mode split, the Monte
//               Carlo time to the solver's accuracy, and the tables' memory; tests/bench/benchmark_report.h)
#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "app/export/color_export.h"
#include "app/export/rgl_channels.h"
#include "app/material/color_channels.h"
#include "app/material/presets.h"
#include "app/process/parallel_for.h"
#include "app/render/table_textures.h"
#include "app/solution/material_solve.h"
#include "app/solution/pair_evaluation.h"
#include "app/solution/solved_document.h"
#include "core/conventions.h"
#include "core/interfaces/interface_operators.h"
#include "core/medium/henyey_greenstein.h"
#include "core/medium/slab_eigen.h"
#include "core/reference/monte_carlo.h"
#include "core/series/quadrature.h"
#include "core/skin/skin_optics.h"
#include "core/solve/batch_solve.h"
#include "core/solve/boundary_solve.h"
#include "core/solve/solve_cache.h"
#include "core/solver.h"
#include "core/unscattered/tabulated_two_interface.h"
#include "core/unscattered/unscattered_light.h"
#include "tests/bench/benchmark_report.h"
#include "tests/bench/solve_stages.h"

namespace skinlayer::bench {
namespace {

// A full single-channel solve at the paper's default (sigma 0.5, eta 1.4, T 0.2, Omega 1, g 0.8, bottom air) at the
// automatic resolution, which tests/core/solver_limits_test.cpp checks is converged to 0.5% in the BRDF.
// Arg 1: the default multiple-scattering interfaces; Arg 0: Stam's single-scattering ones, to price the difference.
void BM_SolveDefault(benchmark::State& state) {
  Material material;
  material.microfacet = state.range(0) == 1 ? MicrofacetModel::Multiple : MicrofacetModel::Single;
  for (auto _ : state) {
    LayerTables tables = solve(material);
    benchmark::DoNotOptimize(tables);
  }
  state.counters["ordinates"] = choose_resolution(material).ordinates;
  state.counters["modes"] = solve(material).modes();
}
BENCHMARK(BM_SolveDefault)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// The machine's unit of dense linear algebra: the eigen-decomposition of one symmetric 64 x 64 matrix (Eigen's
// SelfAdjointEigenSolver, eigenvalues and vectors), the size of the default solve's per-mode eigen-problem (2N = 48
// rounded up). Solve times divided by it compare across machines better than milliseconds do.
void BM_SymmetricEigen64(benchmark::State& state) {
  constexpr int kSize = 64;
  Eigen::MatrixXd matrix(kSize, kSize);
  for (int i = 0; i < kSize; ++i) {
    for (int j = 0; j < kSize; ++j) matrix(i, j) = std::cos(0.37 * (i + 1) * (j + 1)) + (i == j ? kSize : 0.0);
  }
  matrix = 0.5 * (matrix + matrix.transpose()).eval();
  for (auto _ : state) {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(matrix);
    benchmark::DoNotOptimize(eigen.eigenvalues().data());
  }
}
BENCHMARK(BM_SymmetricEigen64)->Unit(benchmark::kMillisecond);

// A stack of n layers like the paper's default (sigma 0.5, eta 1.4, air below; total T 0.2, so n = 1 is the
// default material), the depth shared equally, g 0.8, 0.7, 0.6 and RGB albedos (0.95, 0.7, 0.55), (0.99, 0.8,
// 0.6), (0.9, 0.9, 0.9) top to bottom: a full RGB solve from cold, on both cores (issue 12: two layers within 2.5x
// of one).
std::vector<Material> default_like_stack(int layers) {
  const std::vector<std::array<double, 3>> rgb = {{0.95, 0.7, 0.55}, {0.99, 0.8, 0.6}, {0.9, 0.9, 0.9}};
  const double tau = Material{}.tau / layers;
  std::vector<Material> channels(3);
  for (int c = 0; c < 3; ++c) {
    Material& m = channels[static_cast<std::size_t>(c)];
    m.tau = tau;
    m.albedo = rgb[0][static_cast<std::size_t>(c)];
    for (int i = 1; i < layers; ++i) {
      m.below.push_back({tau, rgb[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)], 0.8 - 0.1 * i, {}});
    }
  }
  return channels;
}
void BM_SolveStack(benchmark::State& state) {
  const std::vector<Material> channels = default_like_stack(static_cast<int>(state.range(0)));
  SolveOptions options;
  options.parallel_for = parallel_for_threads;
  for (auto _ : state) {
    std::vector<LayerTables> tables = solve(channels, options);
    benchmark::DoNotOptimize(tables);
  }
  state.counters["ordinates"] = choose_resolution(channels.front()).ordinates;
  state.counters["modes"] = solve(channels.front()).modes();
}
BENCHMARK(BM_SolveStack)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();

// `skinlayer export --format bsdf` of the default material with an RGB albedo (0.99, 0.9, 0.82) at the
// default nodes (64 per hemisphere) from cold on both cores: the solve, the upside-down solve, the tabulation and
// the encoding (issue 13's target: under 2 s and 20 MB). The file's size is the counter "bytes".
ColorMaterial export_benchmark_material() {
  ColorMaterial material;
  material.albedo_rgb = {0.99, 0.9, 0.82};
  return material;
}
void BM_ExportBsdf(benchmark::State& state) {
  SolveOptions options;
  options.parallel_for = parallel_for_threads;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string file =
        scatfun_file(solve_color(export_benchmark_material(), 0.0, options), kDefaultScatfunNodes, options);
    bytes = file.size();
    benchmark::DoNotOptimize(file.data());
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_ExportBsdf)->Unit(benchmark::kMillisecond)->UseRealTime();

// `export --format rgl` of the same material (issue 26's target: under 2 s and 10 MB on 2 cores): the solve from
// cold, then the spectral form, every node's RGB raised to a sigmoid spectrum, on both cores.
void BM_ExportRgl(benchmark::State& state) {
  SolveOptions options;
  options.parallel_for = parallel_for_threads;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const ColorTables tables = solve_color(export_benchmark_material(), 0.0, options);
    const std::string file = rgl_file(rgl_uplifted_channels(tables), RglOptions{}, "benchmark");
    bytes = file.size();
    benchmark::DoNotOptimize(file.data());
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_ExportRgl)->Unit(benchmark::kMillisecond)->UseRealTime();

// One evaluation of the unscattered BTDF (core/unscattered/unscattered_light.h) at the default material: two rough
// interfaces, the 32 x 32 slope quadrature, near the straight-through direction. The cost of every tables.btdf() call there.
void BM_UnscatteredBtdfTwoInterfaces(benchmark::State& state) {
  const UnscatteredLight light{Material{}};
  double theta_o = degrees_to_radians(40.0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(light.btdf(degrees_to_radians(45.0), theta_o, kPi));
    theta_o = theta_o > degrees_to_radians(50.0) ? degrees_to_radians(40.0) : theta_o + 1e-3;
  }
}
BENCHMARK(BM_UnscatteredBtdfTwoInterfaces)->Unit(benchmark::kMicrosecond);

// eval over a million direction pairs (issue 27's target for the Python module's Solution.eval, which calls
// evaluate_pairs on numpy arrays: under 1 s on 2 cores), on both cores, after the solve. Pairs uniform in
// theta_i, theta_o in [0, 90] and phi in [0, 360) degrees, drawn once. Arg: 0 the grey default (two rough
// interfaces: the unscattered lobe's table, TabulatedTwoInterfaceBtdf, is built in every call), 1 an RGB layer over a
// matched bottom (one rough interface, closed-form unscattered light; the example), 2 the preset skin-medium
// (its spectrum's solves, weighed into RGB), 3 the grey default with the lobe's table kept between calls (as a Python
// Solution keeps it).
void BM_EvalPairs(benchmark::State& state) {
  constexpr std::size_t kPairs = 1'000'000;
  MaterialDocument document;
  if (state.range(0) == 1) {
    document.layer.sigma = 0.3;
    document.layer.tau = optical_depth_from_transparency(0.5);
    document.layer.bottom.kind = BottomKind::Matched;
    document.set_layer_albedo(0, {0.9, 0.7, 0.5});
  } else if (state.range(0) == 2) {
    document = preset_material("skin-medium");
  }
  const SolvedDocument solved = solve_document(document, SubsurfaceModel::Stam, parallel_for_threads);
  std::vector<double> theta_i(kPairs), theta_o(kPairs), phi(kPairs);
  std::mt19937_64 random(27);
  std::uniform_real_distribution<double> polar(0.0, 90.0), azimuth(0.0, 360.0);
  for (std::size_t k = 0; k < kPairs; ++k) {
    theta_i[k] = polar(random);
    theta_o[k] = polar(random);
    phi[k] = azimuth(random);
  }
  const auto channels = static_cast<std::size_t>(value_channels(solved));
  std::vector<double> surface(kPairs), subsurface(kPairs * channels), brdf(kPairs * channels), btdf(kPairs * channels);
  const BsdfArrays out{surface, subsurface, brdf, btdf};
  UnscatteredLobeCache cache;
  UnscatteredLobeCache* kept = state.range(0) == 3 ? &cache : nullptr;
  for (auto _ : state) {
    evaluate_pairs(solved, theta_i, theta_o, phi, out, parallel_for_threads, {}, UnscatteredLobe::Auto, kept);
    benchmark::DoNotOptimize(brdf.data());
  }
  state.counters["pairs"] = static_cast<double>(kPairs);
  state.counters["channels_solved"] = static_cast<double>(solved.tables.size());
}
BENCHMARK(BM_EvalPairs)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();

// The two-interface unscattered lobe's table (core/unscattered/tabulated_two_interface.h) for the default material
// (sigma 0.5: 48 modes) and at the smallest sigma tabulated (0.15: 160 modes, finer theta' panels), on every core.
void BM_TabulateTwoInterfaceLobe(benchmark::State& state) {
  Material material;
  material.sigma = static_cast<double>(state.range(0)) / 100.0;
  const UnscatteredLight light(material);
  for (auto _ : state) {
    TabulatedTwoInterfaceBtdf table(light, parallel_for_threads);
    benchmark::DoNotOptimize(table);
  }
}
BENCHMARK(BM_TabulateTwoInterfaceLobe)->Arg(50)->Arg(15)->Unit(benchmark::kMillisecond)->UseRealTime();

// A single-channel re-solve after one slider step, the cache warm as the previewer's worker keeps it: Omega and T
// reuse the interface operators and the phase projections; g (a new value each step) reuses the interface operators
// and projects the phase function anew; sigma changes the interfaces, so it pays for them (a new value each step).
// BM_Resolve runs on one thread; BM_ResolveParallel hands the executables' parallel-for (app/process/parallel_for.h)
// to the solver, which then solves one channel's modes on every core.
template <typename Change>
void resolve_benchmark(benchmark::State& state, Change change, bool parallel) {
  SolveCache cache;
  SolveOptions options;
  options.cache = &cache;
  if (parallel) options.parallel_for = parallel_for_threads;
  Material material;
  (void)solve(material, options);
  int step = 0;
  for (auto _ : state) {
    change(material, ++step);
    LayerTables tables = solve(material, options);
    benchmark::DoNotOptimize(tables);
  }
  state.counters["cache_hits"] = cache.hits();
}
template <typename Change>
void BM_Resolve(benchmark::State& state, Change change) {
  resolve_benchmark(state, change, false);
}
template <typename Change>
void BM_ResolveParallel(benchmark::State& state, Change change) {
  resolve_benchmark(state, change, true);
}
BENCHMARK_CAPTURE(BM_Resolve, albedo, [](Material& m, int step) {
  m.albedo = step % 2 ? 0.9 : 0.95;
})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Resolve, T, [](Material& m, int step) {
  m.tau = optical_depth_from_transparency(step % 2 ? 0.25 : 0.2);
})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Resolve, g, [](Material& m, int step) {
  m.g = 0.8 - 1e-5 * (step % 1000);
})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Resolve, sigma, [](Material& m, int step) {
  m.sigma = 0.5 + 1e-4 * step;
})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Resolve, sigma_single, [](Material& m, int step) {
  m.microfacet = MicrofacetModel::Single;  // Stam's interfaces: the price of the multiply scattered lobe
  m.sigma = 0.5 + 1e-4 * step;
})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ResolveParallel, albedo, [](Material& m, int step) { m.albedo = step % 2 ? 0.9 : 0.95; })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ResolveParallel, sigma, [](Material& m, int step) { m.sigma = 0.5 + 1e-4 * step; })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The RGB re-solve the previewer's worker runs after one slider step (solve_color: three albedos, and their
// directional albedos at normal incidence for the panel), on both cores with the cache warm (issue 10: <= 6 ms).
template <typename Change>
void BM_ResolveColor(benchmark::State& state, Change change) {
  SolveCache cache;
  SolveOptions options;
  options.cache = &cache;
  options.parallel_for = parallel_for_threads;
  Material material;
  std::vector<double> albedos = {0.95, 0.7, 0.55};
  const std::vector<double> normal = {0.0};
  (void)solve(material, albedos, options);
  (void)directional_albedo(material, normal, albedos, options);
  int step = 0;
  for (auto _ : state) {
    change(material, albedos, ++step);
    std::vector<LayerTables> tables = solve(material, albedos, options);
    benchmark::DoNotOptimize(tables);
    benchmark::DoNotOptimize(directional_albedo(material, normal, albedos, options));
  }
}
BENCHMARK_CAPTURE(BM_ResolveColor, albedo,
                  [](Material&, std::vector<double>& rgb, int step) { rgb[0] = step % 2 ? 0.9 : 0.95; })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ResolveColor, T,
                  [](Material& m, std::vector<double>&, int step) {
                    m.tau = optical_depth_from_transparency(step % 2 ? 0.25 : 0.2);
                  })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ResolveColor, g,
                  [](Material& m, std::vector<double>&, int step) { m.g = 0.8 - 1e-5 * (step % 1000); })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// An RGB re-solve anywhere in the parameter ranges: the costliest corners (a sharp top; a sharp, near-matched top;
// strong forward scattering in a clear layer; a sharp, near-matched bottom), sigma (or the bottom's) stepped each
// time so that the interface operators are built anew, three albedos on both cores as the previewer's worker solves
// them. `preview`: SolveOptions::preview, the worker's first answer; otherwise the full resolution that follows it.
Material costly_corner(int corner) {
  Material m;
  m.tau = optical_depth_from_transparency(0.2);
  switch (corner) {
    case 0:  // sigma 0.05
      m.sigma = 0.05;
      break;
    case 1:  // sigma 0.1, eta 1.05
      m.sigma = 0.1;
      m.eta = 1.05;
      break;
    case 2:  // g 0.95, T 0.9
      m.g = 0.95;
      m.tau = optical_depth_from_transparency(0.9);
      break;
    default:  // bottom sigma 0.2, eta 1.05
      m.bottom.sigma = 0.2;
      m.bottom.eta = 1.05;
      break;
  }
  return m;
}
void BM_ResolveColorCorner(benchmark::State& state, int corner, bool preview) {
  SolveCache cache;
  SolveOptions options;
  options.cache = &cache;
  options.parallel_for = parallel_for_threads;
  options.preview = preview;
  const std::vector<double> albedos = {0.95, 0.7, 0.55};
  Material material = costly_corner(corner);
  const Resolution resolution = choose_resolution(material, options);
  int step = 0;
  for (auto _ : state) {
    const double nudge = 1e-4 * (++step % 100);
    Material changed = material;
    if (corner == 3) {
      changed.bottom.sigma = *material.bottom.sigma + nudge;
    } else {
      changed.sigma = material.sigma + nudge;
    }
    std::vector<LayerTables> tables = solve(changed, albedos, options);
    benchmark::DoNotOptimize(tables);
  }
  state.counters["ordinates"] = resolution.ordinates;
  state.counters["interface_azimuths"] = resolution.interface_azimuths;
}
BENCHMARK_CAPTURE(BM_ResolveColorCorner, sharp_top_preview, 0, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ResolveColorCorner, sharp_top_full, 0, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ResolveColorCorner, near_matched_top_preview, 1, true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ResolveColorCorner, near_matched_top_full, 1, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ResolveColorCorner, forward_clear_preview, 2, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ResolveColorCorner, forward_clear_full, 2, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_ResolveColorCorner, near_matched_bottom_preview, 3, true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_ResolveColorCorner, near_matched_bottom_full, 3, false)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The solve at a fixed number of ordinates per hemisphere, N = 8 .. 128. N = 8 is below the default material's
// minimum (6/sigma and the g = 0.8 phase function need 12), so the sweep uses sigma 0.8 and g 0.5, the rest default.
void BM_SolveOrdinates(benchmark::State& state) {
  Material material = ordinate_sweep_material();
  material.ordinates = static_cast<int>(state.range(0));
  for (auto _ : state) {
    LayerTables tables = solve(material);
    benchmark::DoNotOptimize(tables);
  }
  state.counters["modes"] = solve(material).modes();
}
BENCHMARK(BM_SolveOrdinates)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond);

// The default solve with exactly M Fourier modes (tolerance 0: no early stop).
void BM_SolveFourierModes(benchmark::State& state) {
  const Material material;
  SolveOptions options;
  options.max_modes = static_cast<int>(state.range(0));
  options.fourier_tolerance = 0.0;
  for (auto _ : state) {
    LayerTables tables = solve(material, options);
    benchmark::DoNotOptimize(tables);
  }
}
BENCHMARK(BM_SolveFourierModes)->Arg(1)->Arg(4)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);

// The stages of the default solve (solve_stages.h), each timed over all its modes; the report divides by the modes.
void BM_StagePhaseMatrices(benchmark::State& state) {
  const StageInputs in = default_stage_inputs();
  for (auto _ : state) benchmark::DoNotOptimize(phase_stage(in));
  state.counters["modes"] = in.modes;
}
BENCHMARK(BM_StagePhaseMatrices)->Unit(benchmark::kMillisecond);

void BM_StageInterfaceMatrices(benchmark::State& state) {
  const StageInputs in = default_stage_inputs();
  for (auto _ : state) benchmark::DoNotOptimize(interface_stage(in));
  state.counters["modes"] = in.modes;
}
BENCHMARK(BM_StageInterfaceMatrices)->Unit(benchmark::kMillisecond);

void BM_StageEigen(benchmark::State& state) {
  const StageInputs in = default_stage_inputs();
  const PhaseMatrices phase = phase_stage(in);
  for (auto _ : state) benchmark::DoNotOptimize(eigen_stage(in, phase));
  state.counters["modes"] = in.modes;
}
BENCHMARK(BM_StageEigen)->Unit(benchmark::kMillisecond);

void BM_StageLinearSolve(benchmark::State& state) {
  const StageInputs in = default_stage_inputs();
  const PhaseMatrices phase = phase_stage(in);
  const InterfaceStage interfaces = interface_stage(in);
  const std::vector<SlabEigenSolution> eigen = eigen_stage(in, phase);
  for (auto _ : state) benchmark::DoNotOptimize(linear_solve_stage(in, interfaces, eigen));
  state.counters["modes"] = in.modes;
}
BENCHMARK(BM_StageLinearSolve)->Unit(benchmark::kMillisecond);

void BM_StageSplineTables(benchmark::State& state) {
  const StageInputs in = default_stage_inputs();
  const LayerTables tables = solve(Material{});
  for (auto _ : state) benchmark::DoNotOptimize(spline_stage(tables));
  state.counters["modes"] = in.modes;
}
BENCHMARK(BM_StageSplineTables)->Unit(benchmark::kMillisecond);

// A full spectral skin solve (issue 25, target <= 150 ms on 2 cores): the default skin's tables at 400-700 nm in
// 10 nm steps, from cold (the first wavelength builds the interface operators, the other 30 re-solve with them
// cached), each solve on both cores.
void BM_SpectralSkinSolve(benchmark::State& state) {
  const std::vector<double> wavelengths = wavelength_grid(400.0, 700.0, 10.0);
  std::vector<Material> materials;
  for (const double wavelength : wavelengths) materials.push_back(skin_material(SkinParameters{}, wavelength));
  for (auto _ : state) {
    SolveOptions options;
    options.parallel_for = parallel_for_threads;
    std::vector<LayerTables> tables = solve_batch(materials, options);
    benchmark::DoNotOptimize(tables);
  }
  state.counters["wavelengths"] = static_cast<double>(wavelengths.size());
}
BENCHMARK(BM_SpectralSkinSolve)->Unit(benchmark::kMillisecond)->UseRealTime();

// One skin slider step as the previewer's worker answers it: melanin changes with the cache warm, then solve_color
// (the preview, or the full 31-wavelength solve) and the tables in the GPU layout (make_table_textures), on both
// cores.
void skin_slider_step(benchmark::State& state, bool preview) {
  SolveCache cache;
  SolveOptions options;
  options.cache = &cache;
  options.parallel_for = parallel_for_threads;
  options.preview = preview;
  ColorMaterial material;
  material.layer.sigma = 0.35;
  material.skin = SkinParameters{};
  benchmark::DoNotOptimize(solve_color(material, 0.785, options));
  int step = 0;
  for (auto _ : state) {
    material.skin->melanin = 0.02 + 0.001 * (++step % 10);
    benchmark::DoNotOptimize(make_table_textures(solve_color(material, 0.785, options)));
  }
}

// The previewer's full answer after the slider stops: 31 tables and albedos, mixed to RGB.
void BM_SkinColorSolve(benchmark::State& state) { skin_slider_step(state, false); }
BENCHMARK(BM_SkinColorSolve)->Unit(benchmark::kMillisecond)->UseRealTime();

// A skin slider step while the slider moves (issue 25, target <= 30 ms): solve_color's preview
// (app/solution/material_solve.h: the preview resolution, tables at 400-700 nm in 50 nm steps scaled to the colour of
// all 31 wavelengths' albedos; refined to 10 nm when the slider stops).
void BM_SkinSliderPreview(benchmark::State& state) {
  skin_slider_step(state, true);
  state.counters["tabulated"] = static_cast<double>(skin_preview_wavelengths().size());
}
BENCHMARK(BM_SkinSliderPreview)->Unit(benchmark::kMillisecond)->UseRealTime();

// Directional albedo at four incident angles (what `skinlayer albedo` computes).
void BM_DirectionalAlbedo(benchmark::State& state) {
  const Material material;
  const std::vector<double> theta = {0.0, 0.5236, 1.0472, 1.3963};
  for (auto _ : state) benchmark::DoNotOptimize(directional_albedo(material, theta));
}
BENCHMARK(BM_DirectionalAlbedo)->Unit(benchmark::kMillisecond);

// The Monte Carlo reference at the default material, light at 45 degrees: 100,000 paths on one thread.
void BM_MonteCarloDefault(benchmark::State& state) {
  MonteCarloOptions options;
  options.paths = kMonteCarloBenchPaths;
  options.threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(simulate_layer(Material{}, degrees_to_radians(45.0), {}, options));
}
BENCHMARK(BM_MonteCarloDefault)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace skinlayer::bench

int main(int argc, char** argv) { return skinlayer::bench::run_benchmarks_with_report(argc, argv); }
