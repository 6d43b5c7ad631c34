// The previewer's solve worker: newest parameters win, stale results never come out, the calling (UI) thread never
// waits on a solve, and shutdown never deadlocks.
#include "app/preview/solve_worker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "app/render/table_textures.h"
#include "core/conventions.h"

namespace skinlayer {
namespace {

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr double kMaxCallMilliseconds = 5.0;  // the most a submit() or poll() may take on the UI thread

// The k-th of a sequence of parameter sets that all differ: sigma, g, the RGB albedo, the bottom and the angle.
SolveRequest request_number(int k) {
  SolveRequest request;
  Material& layer = request.material.layer;
  layer.sigma = 0.3 + 0.4 * (k % 97) / 96.0;
  layer.g = 0.4 + 0.4 * (k % 13) / 12.0;
  layer.tau = optical_depth_from_transparency(0.1 + 0.5 * (k % 11) / 10.0);
  if (k % 3 == 1) layer.bottom.kind = BottomKind::Matched;
  if (k % 3 == 2) {
    layer.bottom.kind = BottomKind::Lambert;
    layer.bottom.lambert_albedo = 0.5;
  }
  request.material.albedo_rgb = {0.95 - 0.2 * (k % 7) / 6.0, 0.8, 0.55 + 0.1 * (k % 5) / 4.0};
  request.theta_i = degrees_to_radians(k % 80);
  return request;
}

double milliseconds(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

// Polls until a result of `generation` comes out (every result must be at most that new and newer than the last).
SolveResult wait_for(SolveWorker& worker, std::uint64_t generation, std::chrono::seconds timeout) {
  const auto deadline = Clock::now() + timeout;
  std::uint64_t last = 0;
  while (Clock::now() < deadline) {
    if (std::optional<SolveResult> result = worker.poll()) {
      EXPECT_GT(result->generation, last);
      EXPECT_LE(result->generation, generation);
      last = result->generation;
      if (result->generation == generation) return std::move(*result);
    }
    std::this_thread::sleep_for(1ms);
  }
  ADD_FAILURE() << "no result for generation " << generation << " within " << timeout.count() << " s";
  return {};
}

void expect_same_tables(const ColorTables& shown, const ColorTables& direct) {
  EXPECT_EQ(shown.material.albedo_rgb, direct.material.albedo_rgb);
  EXPECT_EQ(shown.albedo_theta_i, direct.albedo_theta_i);
  for (int c = 0; c < 3; ++c) {
    const LayerTables& a = shown.channels[c];
    const LayerTables& b = direct.channels[c];
    EXPECT_EQ(a.grid_size(), b.grid_size()) << "channel " << c;
    EXPECT_EQ(a.modes(), b.modes()) << "channel " << c;
    EXPECT_TRUE(std::ranges::equal(a.reflection_coefficients(), b.reflection_coefficients())) << "channel " << c;
    EXPECT_TRUE(std::ranges::equal(a.transmission_coefficients(), b.transmission_coefficients())) << "channel " << c;
    EXPECT_EQ(shown.albedo[c].reflectance_surface, direct.albedo[c].reflectance_surface) << "channel " << c;
    EXPECT_EQ(shown.albedo[c].reflectance_subsurface, direct.albedo[c].reflectance_subsurface) << "channel " << c;
    EXPECT_EQ(shown.albedo[c].transmittance, direct.albedo[c].transmittance) << "channel " << c;
    EXPECT_EQ(shown.albedo[c].absorptance, direct.albedo[c].absorptance) << "channel " << c;
  }
}

TEST(SolveWorker, AThousandRapidChangesEndOnTheFinalParametersWithoutStalls) {
  SolveWorker worker;
  double longest_submit = 0.0, longest_poll = 0.0;
  std::uint64_t last_generation = 0, last_seen = 0;
  int results_seen = 0;
  constexpr int kChanges = 1000;
  for (int k = 0; k < kChanges; ++k) {
    const SolveRequest request = request_number(k);
    const auto submit_start = Clock::now();
    last_generation = worker.submit(request);
    longest_submit = std::max(longest_submit, milliseconds(Clock::now() - submit_start));

    const auto poll_start = Clock::now();
    std::optional<SolveResult> result = worker.poll();
    longest_poll = std::max(longest_poll, milliseconds(Clock::now() - poll_start));
    if (result) {
      EXPECT_GT(result->generation, last_seen) << "results come out newest-last, each once";
      last_seen = result->generation;
      ++results_seen;
    }
    std::this_thread::sleep_for(300us);  // a fast drag: a change every third of a millisecond (~0.4 s in all)
  }
  EXPECT_EQ(last_generation, static_cast<std::uint64_t>(kChanges));

  const SolveResult final_result = wait_for(worker, last_generation, 120s);
  ASSERT_EQ(final_result.generation, last_generation);
  ASSERT_EQ(final_result.error, "");
  EXPECT_TRUE(same_request(final_result.request, request_number(kChanges - 1)));
  EXPECT_FALSE(worker.busy());
  EXPECT_FALSE(worker.poll().has_value()) << "a result comes out once";

  const SolveRequest final_request = request_number(kChanges - 1);
  const ColorTables direct = solve_color(final_request.material, final_request.theta_i);
  expect_same_tables(final_result.tables(), direct);
  const TableTextureData textures = make_table_textures(direct);
  EXPECT_EQ(final_result.textures().size, textures.size);
  EXPECT_EQ(final_result.textures().modes, textures.modes);
  EXPECT_EQ(final_result.textures().reflection, textures.reflection);
  EXPECT_EQ(final_result.textures().transmission, textures.transmission);

  const SolveWorkerStats stats = worker.stats();
  std::printf(
      "[ worker  ] %d submits: longest submit() %.3f ms, longest poll() %.3f ms; %llu solves, %llu stale "
      "results discarded, %d intermediate results polled; final solve %.1f ms\n",
      kChanges, longest_submit, longest_poll, static_cast<unsigned long long>(stats.solved),
      static_cast<unsigned long long>(stats.discarded), results_seen, 1000.0 * final_result.seconds);
  RecordProperty("longest_submit_ms", std::to_string(longest_submit));
  RecordProperty("longest_poll_ms", std::to_string(longest_poll));
  EXPECT_LT(longest_submit, kMaxCallMilliseconds);
  EXPECT_LT(longest_poll, kMaxCallMilliseconds);
  EXPECT_LT(stats.solved, static_cast<std::uint64_t>(kChanges)) << "pending requests are coalesced";
}

TEST(SolveWorker, ASupersededRequestNeverComesOut) {
  SolveWorker worker;
  SolveRequest slow = request_number(0);
  slow.material.layer.ordinates = 64;  // long enough to be superseded while it is solved
  const std::uint64_t first = worker.submit(slow);
  std::this_thread::sleep_for(5ms);  // let the worker start it
  const std::uint64_t second = worker.submit(request_number(1));
  ASSERT_GT(second, first);
  const SolveResult result = wait_for(worker, second, 120s);  // fails on any result of `first`
  EXPECT_EQ(result.generation, second);
  EXPECT_TRUE(same_request(result.request, request_number(1)));
}

// Polls until a result comes out (or the timeout passes: then a failure and an empty result).
SolveResult next_result(SolveWorker& worker, std::chrono::seconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (Clock::now() < deadline) {
    if (std::optional<SolveResult> result = worker.poll()) return std::move(*result);
    std::this_thread::sleep_for(1ms);
  }
  ADD_FAILURE() << "no result within " << timeout.count() << " s";
  return {};
}

TEST(SolveWorker, ACostlyMaterialShowsAPreviewThenSettlesOnTheFullSolve) {
  SolveRequest request = request_number(3);
  request.material.layer.sigma = 0.15;  // N 44 and 161 interface azimuths at full resolution
  ASSERT_TRUE(preview_is_coarser(request.material.layer));
  SolveWorker worker;
  const std::uint64_t generation = worker.submit(request);
  const SolveResult preview = next_result(worker, 120s);
  EXPECT_EQ(preview.generation, generation);
  EXPECT_TRUE(preview.preview) << "the quick look comes first";
  EXPECT_EQ(preview.error, "");
  const SolveResult final_result = next_result(worker, 120s);
  EXPECT_EQ(final_result.generation, generation);
  EXPECT_FALSE(final_result.preview);
  EXPECT_FALSE(worker.settling());
  EXPECT_FALSE(worker.poll().has_value()) << "two results for one request, each once";
  expect_same_tables(final_result.tables(), solve_color(request.material, request.theta_i));
  const SolveWorkerStats stats = worker.stats();
  EXPECT_EQ(stats.previews, 1u);
  EXPECT_EQ(stats.solved, 2u);
  std::printf("[ worker  ] sigma 0.15 RGB: preview %.1f ms, full solve %.1f ms\n", 1000.0 * preview.seconds,
              1000.0 * final_result.seconds);
}

TEST(SolveWorker, NewerParametersAbandonARefinement) {
  SolveRequest sharp = request_number(4);
  sharp.material.layer.sigma = 0.05;  // its full solve takes seconds
  SolveWorker worker;
  const std::uint64_t first = worker.submit(sharp);
  const SolveResult preview = next_result(worker, 120s);
  ASSERT_EQ(preview.generation, first);
  ASSERT_TRUE(preview.preview);
  EXPECT_TRUE(worker.settling()) << "its full solve runs";
  EXPECT_FALSE(worker.busy()) << "newer parameters may be submitted now";
  const auto submitted_at = Clock::now();
  const std::uint64_t second = worker.submit(request_number(5));
  const SolveResult next = next_result(worker, 120s);
  EXPECT_EQ(next.generation, second) << "the first request's full solve never comes out";
  EXPECT_FALSE(next.preview);
  const SolveWorkerStats stats = worker.stats();
  EXPECT_EQ(stats.cancelled + stats.discarded, 1u) << "the refinement was abandoned or dropped";
  std::printf("[ worker  ] a refinement at sigma 0.05 gave way to newer parameters in %.1f ms (%llu cancelled)\n",
              milliseconds(Clock::now() - submitted_at), static_cast<unsigned long long>(stats.cancelled));
}

// A burst: four threads submit 250 requests each back to back while the owner polls. Each generation answers the
// request it was returned for, results come out newest-last and each once, and the newest of the thousand wins.
TEST(SolveWorker, TheNewestOfABurstOfAThousandRequestsWins) {
  constexpr int kThreads = 4, kPerThread = 250, kRequests = kThreads * kPerThread;
  SolveWorker worker;
  std::mutex mutex;
  std::vector<int> request_of_generation(kRequests + 1, -1);  // which request_number() got each generation
  std::atomic<int> submitters_done{0};
  std::uint64_t last_seen = 0;
  int results_seen = 0;
  {
    std::vector<std::jthread> submitters;
    for (int t = 0; t < kThreads; ++t) {
      submitters.emplace_back([&, t] {
        for (int i = 0; i < kPerThread; ++i) {
          const int k = t * kPerThread + i;
          const std::uint64_t generation = worker.submit(request_number(k));
          const std::lock_guard lock(mutex);
          request_of_generation.at(generation) = k;
        }
        ++submitters_done;
      });
    }
    while (submitters_done.load() < kThreads) {  // the owner polls while the burst goes on
      if (std::optional<SolveResult> result = worker.poll()) {
        EXPECT_GT(result->generation, last_seen) << "results come out newest-last, each once";
        last_seen = result->generation;
        ++results_seen;
        const std::lock_guard lock(mutex);
        const int k = request_of_generation.at(result->generation);
        if (k >= 0) {
          EXPECT_TRUE(same_request(result->request, request_number(k))) << "generation " << k;
        }
      }
    }
  }
  ASSERT_TRUE(std::ranges::none_of(request_of_generation.begin() + 1, request_of_generation.end(),
                                   [](int k) { return k < 0; }))
      << "every submit got its own generation, 1 to " << kRequests;
  const int newest = request_of_generation.back();
  const SolveResult final_result = wait_for(worker, kRequests, 120s);
  ASSERT_EQ(final_result.error, "");
  EXPECT_TRUE(same_request(final_result.request, request_number(newest)));
  EXPECT_FALSE(worker.busy());
  EXPECT_FALSE(worker.settling());
  EXPECT_FALSE(worker.poll().has_value());
  const SolveRequest& request = final_result.request;
  expect_same_tables(final_result.tables(), solve_color(request.material, request.theta_i));
  const SolveWorkerStats stats = worker.stats();
  std::printf("[ worker  ] a burst of %d requests from %d threads: %llu solves, %llu cancelled, %d results polled\n",
              kRequests, kThreads, static_cast<unsigned long long>(stats.solved),
              static_cast<unsigned long long>(stats.cancelled), results_seen);
  EXPECT_LT(stats.solved, static_cast<std::uint64_t>(kRequests / 10)) << "pending requests are coalesced";
}

// Sharp interfaces (sigma 0.05, 120 ordinates): the interface kernels take the first half of its full solve. It has a
// preview phase first.
SolveRequest kernel_bound_request() {
  SolveRequest request = request_number(2);
  request.material.layer.sigma = 0.05;
  return request;
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Submits the request and returns once its full-resolution solve has begun (its preview, if any, is out).
std::uint64_t submit_up_to_the_full_solve(SolveWorker& worker, const SolveRequest& request) {
  const std::uint64_t generation = worker.submit(request);
  if (preview_is_coarser(request.material.layer)) {
    EXPECT_TRUE(next_result(worker, 120s).preview);
  }
  return generation;
}

// How long the worker's full solve of a request takes, from its start (after its preview) to its result.
double full_solve_seconds(const SolveRequest& request) {
  SolveWorker worker;
  const std::uint64_t generation = submit_up_to_the_full_solve(worker, request);
  const auto start = Clock::now();
  while (worker.settling()) std::this_thread::sleep_for(1ms);
  const double seconds = seconds_since(start);
  EXPECT_EQ(wait_for(worker, generation, 1s).error, "");
  return seconds;
}

// Newer parameters stop a solve inside its interface kernels (core asks the worker once per incident direction),
// not after them: submitted a tenth into the full solve, the newer request's result comes out far sooner than the
// abandoned kernels would have taken to end (another third of the solve). The abandoned build leaves nothing
// behind: the same request solved again through the worker's cache is the cold solve exactly.
TEST(SolveWorker, ANewerRequestStopsASolveInsideItsInterfaceKernels) {
  const SolveRequest slow = kernel_bound_request();
  const SolveRequest fast = request_number(7);
  const double slow_seconds = full_solve_seconds(slow), fast_seconds = full_solve_seconds(fast);

  SolveWorker worker;
  submit_up_to_the_full_solve(worker, slow);
  std::this_thread::sleep_for(std::chrono::duration<double>(0.1 * slow_seconds));
  const auto submitted = Clock::now();
  const std::uint64_t generation = worker.submit(fast);
  const SolveResult result = wait_for(worker, generation, 120s);  // fails on any result of the slow request
  const double waited = seconds_since(submitted);
  EXPECT_EQ(result.generation, generation);
  EXPECT_EQ(worker.stats().cancelled, 1u);
  std::printf("[ worker  ] full solve at sigma 0.05 %.0f ms, a cheap one %.0f ms; the cheap one, submitted %.0f ms into "
              "the first, came out after %.0f ms\n",
              1000.0 * slow_seconds, 1000.0 * fast_seconds, 100.0 * slow_seconds, 1000.0 * waited);
  EXPECT_LT(waited, fast_seconds + 0.15 * slow_seconds);

  const std::uint64_t again = submit_up_to_the_full_solve(worker, slow);
  const SolveResult resolved = wait_for(worker, again, 300s);
  ASSERT_EQ(resolved.error, "");
  ASSERT_FALSE(resolved.preview);
  expect_same_tables(resolved.tables(), solve_color(slow.material, slow.theta_i));
}

// Shutdown inside the kernels stops them at once rather than waiting for the build to end.
TEST(SolveWorker, DestroyingItInsideTheInterfaceKernelsReturnsPromptly) {
  const SolveRequest slow = kernel_bound_request();
  const double slow_seconds = full_solve_seconds(slow);
  auto worker = std::make_unique<SolveWorker>();
  submit_up_to_the_full_solve(*worker, slow);
  std::this_thread::sleep_for(std::chrono::duration<double>(0.1 * slow_seconds));
  const auto start = Clock::now();
  worker.reset();
  const double shutdown = seconds_since(start);
  std::printf("[ worker  ] shutdown inside a %.0f ms full solve took %.1f ms\n", 1000.0 * slow_seconds,
              1000.0 * shutdown);
  EXPECT_LT(shutdown, 0.15 * slow_seconds);
}

TEST(SolveWorker, AnInvalidMaterialComesBackAsAnError) {
  SolveWorker worker;
  SolveRequest request;
  request.material.layer.sigma = 7.0;
  const std::uint64_t generation = worker.submit(request);
  const SolveResult result = wait_for(worker, generation, 60s);
  EXPECT_NE(result.error.find("sigma"), std::string::npos) << result.error;
  EXPECT_EQ(result.textures().modes, 0);
}

TEST(SolveWorker, PublishingWakesTheOwner) {
  std::atomic<int> wakes = 0;
  {
    SolveWorker worker([&wakes] { ++wakes; });
    const std::uint64_t generation = worker.submit(SolveRequest{});
    wait_for(worker, generation, 60s);
  }
  EXPECT_EQ(wakes.load(), 1);
}

TEST(SolveWorker, DestroyingItDuringASolveReturns) {
  const auto start = Clock::now();
  {
    SolveWorker worker;
    worker.submit(request_number(5));
    std::this_thread::sleep_for(2ms);
    worker.submit(request_number(6));  // pending while the first is solved: dropped at shutdown
  }
  std::printf("[ worker  ] shutdown with a solve in flight took %.1f ms\n", milliseconds(Clock::now() - start));
  SUCCEED();
}

}  // namespace
}  // namespace skinlayer
