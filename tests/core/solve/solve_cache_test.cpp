// The caller-owned cache of interface operators (core/solve/solve_cache.h) and the caller's parallel-for
// (SolveOptions::parallel_for): neither may change a single bit of the result.
#include "core/solve/solve_cache.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <thread>
#include <vector>

#include "core/solver.h"

namespace skinlayer {
namespace {

void expect_identical(const LayerTables& a, const LayerTables& b, const char* what) {
  ASSERT_EQ(a.modes(), b.modes()) << what;
  EXPECT_TRUE(std::ranges::equal(a.reflection_coefficients(), b.reflection_coefficients())) << what;
  EXPECT_TRUE(std::ranges::equal(a.transmission_coefficients(), b.transmission_coefficients())) << what;
}

TEST(SolveCache, ACachedResolveEqualsAnUncachedSolveBitForBit) {
  SolveCache cache;
  SolveOptions cached;
  cached.cache = &cache;
  Material m;
  m.sigma = 0.3;
  (void)solve(m, cached);  // warms the cache: the interface operators and the phase projections
  EXPECT_EQ(cache.misses(), 2);
  for (const auto& change : std::vector<void (*)(Material&)>{
           [](Material& x) { x.albedo = 0.7; },
           [](Material& x) { x.tau = optical_depth_from_transparency(0.25); },
           [](Material& x) { x.g = 0.75; },
           [](Material& x) { x.bottom = parse_bottom("lambert:0.4"); },
       }) {
    Material changed = m;
    change(changed);
    const int hits = cache.hits();
    const LayerTables from_cache = solve(changed, cached);
    expect_identical(from_cache, solve(changed), "albedo, T, g or the Lambert base's albedo changed");
    if (changed.bottom.kind == BottomKind::Air) {
      EXPECT_GE(cache.hits(), hits + 1) << "the interfaces did not change";
    }
  }
  // Directional albedos share the cache too (their own outside directions), and agree exactly.
  const std::vector<double> angles = {0.0, 0.7};
  const std::vector<DirectionalAlbedo> first = directional_albedo(m, angles, cached);
  const std::vector<DirectionalAlbedo> again = directional_albedo(m, angles, cached);
  const std::vector<DirectionalAlbedo> plain = directional_albedo(m, angles);
  for (std::size_t k = 0; k < angles.size(); ++k) {
    EXPECT_EQ(again[k].reflectance_subsurface, plain[k].reflectance_subsurface);
    EXPECT_EQ(first[k].transmittance, plain[k].transmittance);
  }
}

TEST(SolveCache, AnInterfaceChangeIsAMissAndTheBudgetBoundsMemory) {
  SolveCache cache;
  SolveOptions cached;
  cached.cache = &cache;
  Material m;
  (void)solve(m, cached);
  m.sigma = 0.45;  // same N (24), other interface
  (void)solve(m, cached);
  m.bottom.eta = 1.3;
  (void)solve(m, cached);
  // Three interface builds; the phase projections (same g and resolution) were built once and reused twice.
  EXPECT_EQ(cache.misses(), 4);
  EXPECT_EQ(cache.hits(), 2);
  EXPECT_EQ(cache.entries(), 4u);

  const std::size_t budget = cache.bytes() / 2;  // room for about two of the four entries
  SolveCache small(budget);
  SolveOptions bounded;
  bounded.cache = &small;
  for (const double sigma : {0.5, 0.45, 0.4, 0.35}) {
    Material x;
    x.sigma = sigma;
    (void)solve(x, bounded);
    EXPECT_LE(small.bytes(), budget);
  }
  EXPECT_GE(small.entries(), 1u);
  EXPECT_LT(small.entries(), 4u);
  SolveCache none(1);  // smaller than any entry: nothing is kept, the solve still works
  bounded.cache = &none;
  EXPECT_GT(solve(Material{}, bounded).modes(), 0);
  EXPECT_EQ(none.entries(), 0u);
}

// A caller's parallel-for (threads here) runs the albedos side by side; every channel equals its serial solve.
TEST(SolveCache, ParallelAlbedosEqualSerialOnes) {
  SolveOptions parallel;
  int calls = 0;
  parallel.parallel_for = [&calls](int count, const std::function<void(int)>& body) {
    ++calls;
    std::vector<std::jthread> threads;
    for (int index = 0; index < count; ++index) threads.emplace_back([&body, index] { body(index); });
  };
  const Material m;
  const std::vector<double> albedos = {0.95, 0.7, 0.55};
  const std::vector<LayerTables> side_by_side = solve(m, albedos, parallel);
  const std::vector<LayerTables> serial = solve(m, albedos);
  EXPECT_GE(calls, 1);
  for (std::size_t c = 0; c < albedos.size(); ++c) expect_identical(side_by_side[c], serial[c], "channel");
  // One albedo: its Fourier modes side by side, four at a time; the modes past convergence are discarded.
  calls = 0;
  for (const double g : {0.8, 0.95}) {
    Material one = m;
    one.g = g;
    expect_identical(solve(one, parallel), solve(one), "modes in parallel");
  }
  EXPECT_GE(calls, 4);
  // The interface kernels (top reflection, top transmission, a bottom unlike the top, an open top's bottom beam)
  // are built side by side too.
  Material unlike_bottom = m;
  unlike_bottom.bottom.sigma = 0.3;
  unlike_bottom.bottom.eta = 1.2;
  Material open_top = unlike_bottom;
  open_top.eta = 1.0;
  Material matched = m;
  matched.bottom.kind = BottomKind::Matched;
  for (const Material& kind : {unlike_bottom, open_top, matched}) {
    calls = 0;
    expect_identical(solve(kind, parallel), solve(kind), "interface kernels in parallel");
    EXPECT_GE(calls, 2);
  }
}

}  // namespace
}  // namespace skinlayer
