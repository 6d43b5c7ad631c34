// The solver's parallel paths on the executables' own parallel-for (app/process/parallel_for.h): RGB channels side
// by side, a stack's internal interfaces and mode blocks, a skin's spectrum in chunks with copies of a warm cache,
// and solves on several threads at once. Each must give the serial answer bit for bit. `./setup.sh test` runs these
// under ThreadSanitizer (build-tsan/, ctest -L threads), where any data race fails them.
//
// And cancellation (core/cancellation.h): a solve stops inside its interface kernels when asked, from its own
// threads or from another one, and leaves no half-built entry in the caller's cache.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "app/process/parallel_for.h"
#include "core/skin/skin_optics.h"
#include "core/skin/skin_spectrum.h"
#include "core/solve/batch_solve.h"
#include "core/solve/solve_cache.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

bool same_tables(const LayerTables& a, const LayerTables& b) {
  return a.grid_size() == b.grid_size() && a.modes() == b.modes() &&
         std::ranges::equal(a.reflection_coefficients(), b.reflection_coefficients()) &&
         std::ranges::equal(a.transmission_coefficients(), b.transmission_coefficients());
}

SolveOptions threaded(SolveCache* cache = nullptr) {
  SolveOptions options;
  options.parallel_for = parallel_for_threads;
  options.cache = cache;
  return options;
}

// A three-layer stack with rough interfaces between its layers and a rough bottom: every kernel family is built. On
// 20 ordinates, the fewest it takes: the threads split the same work the same way, and these tests also run
// under ThreadSanitizer, ten times slower.
Material rough_stack() {
  Material material;
  material.ordinates = 20;
  material.sigma = 0.4;
  material.tau = 0.5;
  material.albedo = 0.9;
  material.g = 0.6;
  material.below.push_back({0.8, 0.95, 0.3, LayerInterface{0.3, 1.1}});
  material.below.push_back({1.2, 0.7, 0.8, LayerInterface{0.6, 0.95}});
  return material;
}

TEST(ParallelSolve, RgbChannelsSideBySideEqualEachChannelAlone) {
  std::vector<Material> channels(3);
  channels[0].albedo = 0.99;
  channels[1].albedo = 0.8;
  channels[2].albedo = 0.5;
  SolveCache cache;
  const std::vector<LayerTables> side_by_side = solve(channels, threaded(&cache));
  ASSERT_EQ(side_by_side.size(), channels.size());
  for (std::size_t c = 0; c < channels.size(); ++c) {
    EXPECT_TRUE(same_tables(side_by_side[c], solve(channels[c]))) << "channel " << c;
  }
}

TEST(ParallelSolve, AStackWithRoughInternalInterfacesEqualsItsSerialSolve) {
  const Material stack = rough_stack();
  SolveCache cache;
  const LayerTables parallel = solve(stack, threaded(&cache));
  EXPECT_TRUE(same_tables(parallel, solve(stack)));
  EXPECT_TRUE(same_tables(solve(stack, threaded(&cache)), parallel)) << "the warm cache changes nothing";
}

TEST(ParallelSolve, ASkinSpectrumInChunksEqualsOneSolvePerWavelength) {
  SkinParameters skin;
  std::vector<Material> wavelengths;
  for (const double nm : {420.0, 460.0, 500.0, 542.0, 577.0, 620.0, 660.0, 700.0}) {
    wavelengths.push_back(skin_material(skin, nm));
  }
  SolveCache cache;
  const std::vector<LayerTables> batch = solve_batch(wavelengths, threaded(&cache));
  ASSERT_EQ(batch.size(), wavelengths.size());
  for (std::size_t k = 0; k < wavelengths.size(); ++k) {
    EXPECT_TRUE(same_tables(batch[k], solve(wavelengths[k]))) << "wavelength " << k;
  }

  const std::vector<double> nm = {450.0, 550.0, 650.0};
  const std::vector<double> theta_i = {0.0, 0.7, 1.3};
  const auto threaded_albedo = skin_directional_albedo(skin, Material{}, nm, theta_i, threaded());
  const auto serial_albedo = skin_directional_albedo(skin, Material{}, nm, theta_i);
  ASSERT_EQ(threaded_albedo.size(), serial_albedo.size());
  for (std::size_t k = 0; k < nm.size(); ++k) {
    for (std::size_t j = 0; j < theta_i.size(); ++j) {
      EXPECT_EQ(threaded_albedo[k][j].reflectance_subsurface, serial_albedo[k][j].reflectance_subsurface);
      EXPECT_EQ(threaded_albedo[k][j].transmittance, serial_albedo[k][j].transmittance);
    }
  }
}

// Core keeps no hidden state: solves on several threads at once, each with its own cache and parallel-for, share
// nothing mutable (the embedded tables, quadratures and projectors are built per call or are immutable).
TEST(ParallelSolve, SolvesOnSeveralThreadsAtOnceEqualTheirSerialSolves) {
  std::vector<Material> materials(4);
  materials[1] = rough_stack();
  materials[2].bottom.kind = BottomKind::Matched;
  materials[3] = skin_material(SkinParameters{}, 577.0);
  std::vector<LayerTables> concurrent(materials.size());
  {
    std::vector<std::jthread> threads;
    for (std::size_t k = 0; k < materials.size(); ++k) {
      threads.emplace_back([&, k] {
        SolveCache cache;
        concurrent[k] = solve(materials[k], threaded(&cache));
      });
    }
  }
  for (std::size_t k = 0; k < materials.size(); ++k) {
    EXPECT_TRUE(same_tables(concurrent[k], solve(materials[k]))) << "material " << k;
  }
}

// How often a solve asks its cancellation check, and the answer it gives; thread-safe (the solver asks it from the
// parallel-for's threads).
class CountingCheck {
 public:
  explicit CountingCheck(long cancel_after = -1) : cancel_after_(cancel_after) {}
  CancelCheck check() {
    return [this] {
      const long asked = ++asked_;
      return cancel_after_ >= 0 && asked > cancel_after_;
    };
  }
  long asked() const { return asked_.load(); }

 private:
  long cancel_after_;
  std::atomic<long> asked_{0};
};

// The interface kernels ask once per incident direction of every kernel they build: a solve that builds them asks
// many more times than the same solve with them cached, which asks only between its stages (before each mode).
TEST(SolveCancellation, TheInterfaceKernelsAskOncePerIncidentDirection) {
  Material material;
  material.ordinates = 24;
  SolveCache cache;
  CountingCheck cold;
  SolveOptions options = threaded(&cache);
  options.cancelled = cold.check();
  const LayerTables first = solve(material, options);
  CountingCheck warm;
  options.cancelled = warm.check();
  const LayerTables second = solve(material, options);
  EXPECT_TRUE(same_tables(first, second));
  std::printf("[ cancel  ] checks asked: %ld building the interface kernels, %ld with them cached\n", cold.asked(),
              warm.asked());
  // The top's reflection between the 24 nodes alone asks twice per node (its lobes' support, then the samples).
  EXPECT_GE(cold.asked() - warm.asked(), 2 * 24);
  EXPECT_LE(warm.asked(), first.modes() + 5) << "cached, only the stages ask (modes solved in blocks of 4)";
}

// Cancelled after a few checks, the solve is inside its first interface kernels: it throws, soon, and the cache
// holds nothing of the abandoned build, so that the next solve with the same cache is the cold solve exactly.
TEST(SolveCancellation, StopsInsideTheInterfaceKernelsAndCachesNothingHalfBuilt) {
  const Material material = rough_stack();
  CountingCheck uncancelled;
  SolveOptions counting = threaded();
  counting.cancelled = uncancelled.check();
  const LayerTables reference = solve(material, counting);

  SolveCache cache;
  constexpr long kCancelAfter = 3;
  CountingCheck cancel(kCancelAfter);
  SolveOptions options = threaded(&cache);
  options.cancelled = cancel.check();
  EXPECT_THROW(solve(material, options), SolveCancelled);
  EXPECT_EQ(cache.entries(), 0u) << "a cancelled build caches nothing";
  // Every thread of the parallel-for stops at its next check: a few more than kCancelAfter, far from a whole solve.
  EXPECT_LE(cancel.asked(), kCancelAfter + 8);
  EXPECT_LT(cancel.asked(), uncancelled.asked() / 4);

  options.cancelled = {};
  EXPECT_TRUE(same_tables(solve(material, options), reference));
  EXPECT_GT(cache.entries(), 0u);
}

// The previewer's case: another thread (the UI's submit) asks for the stop while the solve's threads are inside
// the kernels; the flag crosses threads through an atomic, and the solve ends with SolveCancelled.
TEST(SolveCancellation, AnotherThreadStopsASolveInsideItsKernels) {
  Material material = rough_stack();
  material.ordinates = 48;  // a long kernel build
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::condition_variable started;
  bool inside = false;
  SolveOptions options = threaded();
  options.cancelled = [&] {
    {
      const std::lock_guard lock(mutex);
      inside = true;
    }
    started.notify_one();
    return stop.load();
  };
  std::jthread canceller([&] {
    std::unique_lock lock(mutex);
    started.wait(lock, [&] { return inside; });
    stop = true;
  });
  EXPECT_THROW(solve(material, options), SolveCancelled);
}

}  // namespace
}  // namespace skinlayer
