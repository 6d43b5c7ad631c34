// The previewer's solve worker: newest parameters win, stale results never come out, the calling (UI) thread never
// waits on a solve, cancellation reaches inside the solver's kernels, and shutdown never deadlocks.
//
// No test here reads a clock. The properties are shown by construction instead: a solve held on a latch that the
// test owns (submit() and poll() return while it is known to be blocked), and the solve's cancellation checks
// watched one by one (a solve told to stop asks no further question in any piece of its work). Waiting for a result
// blocks on the worker's publication callback without a deadline; a hang runs into ctest's TIMEOUT.
#include "app/preview/solve_worker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <latch>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "app/render/table_textures.h"
#include "core/conventions.h"
#include "core/parallel_for.h"

namespace skinlayer {
namespace {

using namespace std::chrono_literals;

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

// Counts the worker's publications (its on_published callback) and lets the owner sleep until the next one.
class Publications {
 public:
  std::function<void()> callback() {
    return [this] {
      {
        const std::lock_guard lock(mutex_);
        ++count_;
      }
      published_.notify_all();
    };
  }
  std::uint64_t count() const {
    const std::lock_guard lock(mutex_);
    return count_;
  }
  // Blocks until more than `seen` results have been published.
  void wait_past(std::uint64_t seen) {
    std::unique_lock lock(mutex_);
    published_.wait(lock, [&] { return count_ > seen; });
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable published_;
  std::uint64_t count_ = 0;
};

// The next result out of poll(), sleeping between publications.
SolveResult next_result(SolveWorker& worker, Publications& publications) {
  while (true) {
    const std::uint64_t seen = publications.count();
    if (std::optional<SolveResult> result = worker.poll()) return std::move(*result);
    publications.wait_past(seen);
  }
}

// Polls until a result of `generation` comes out; every result on the way must be at most that new and newer than
// the last.
SolveResult wait_for(SolveWorker& worker, Publications& publications, std::uint64_t generation) {
  std::uint64_t last = 0;
  while (true) {
    SolveResult result = next_result(worker, publications);
    EXPECT_GT(result.generation, last);
    EXPECT_LE(result.generation, generation);
    last = result.generation;
    if (result.generation >= generation) return result;
  }
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

void expect_solved_as_directly(const SolveResult& result) {
  ASSERT_EQ(result.error, "");
  const SolveRequest& request = result.request;
  const ColorTables direct = solve_color(request.material, request.theta_i);
  expect_same_tables(result.tables(), direct);
  const TableTextureData textures = make_table_textures(direct);
  EXPECT_EQ(result.textures().size, textures.size);
  EXPECT_EQ(result.textures().modes, textures.modes);
  EXPECT_EQ(result.textures().reflection, textures.reflection);
  EXPECT_EQ(result.textures().transmission, textures.transmission);
}

// A solve function that holds the first phase it runs (or the first full, not preview, phase) until the test releases
// it, then solves as the worker would (compute_solve). `entered` opens when the held phase has begun;
// `solve_returned` says whether it has ended.
class HeldFirstSolve {
 public:
  enum class Phase { Any, Full };
  explicit HeldFirstSolve(Phase phase = Phase::Any) : phase_(phase) {}

  SolveFunction function() {
    return [this](const SolveRequest& request, std::uint64_t generation, const SolveOptions& options) {
      const bool holds = phase_ == Phase::Any || !options.preview;
      if (holds && !held_.exchange(true)) {
        entered_.count_down();
        release_.wait();
        try {
          SolveResult result = compute_solve(request, generation, options);
          solve_returned_ = true;
          return result;
        } catch (...) {
          solve_returned_ = true;
          throw;
        }
      }
      return compute_solve(request, generation, options);
    };
  }
  void wait_until_entered() { entered_.wait(); }
  void release() { release_.count_down(); }
  bool solve_returned() const { return solve_returned_.load(); }

 private:
  Phase phase_;
  std::atomic<bool> held_{false};
  std::atomic<bool> solve_returned_{false};
  std::latch entered_{1};
  std::latch release_{1};
};

// submit() and poll() never wait for a solve: a thousand of each return while the worker's solve is held on a latch
// (a submit that waited for it would never return, and the test would hang into ctest's timeout). Pending requests
// coalesce: once released, the held solve is abandoned at its first cancellation check and only the newest of the
// thousand is solved; the 998 between are never solved at all.
TEST(SolveWorker, SubmitAndPollReturnWhileASolveIsHeld) {
  Publications publications;
  HeldFirstSolve held;
  SolveWorker worker(publications.callback(), held.function());
  constexpr int kChanges = 1000;
  worker.submit(request_number(0));
  held.wait_until_entered();
  std::uint64_t last_generation = 0;
  for (int k = 1; k <= kChanges; ++k) {
    last_generation = worker.submit(request_number(k));
    EXPECT_FALSE(worker.poll().has_value()) << "nothing is published while the solve is held";
    EXPECT_TRUE(worker.busy());
    EXPECT_TRUE(worker.settling());
  }
  EXPECT_FALSE(held.solve_returned()) << "every submit and poll returned while the solve was held";
  EXPECT_EQ(last_generation, static_cast<std::uint64_t>(kChanges + 1));
  held.release();

  const SolveResult final_result = wait_for(worker, publications, last_generation);
  EXPECT_TRUE(held.solve_returned());
  EXPECT_EQ(final_result.generation, last_generation);
  EXPECT_TRUE(same_request(final_result.request, request_number(kChanges)));
  if (final_result.preview) {
    const SolveResult settled = next_result(worker, publications);
    EXPECT_EQ(settled.generation, last_generation);
    EXPECT_FALSE(settled.preview);
    expect_solved_as_directly(settled);
  } else {
    expect_solved_as_directly(final_result);
  }
  EXPECT_FALSE(worker.busy());
  EXPECT_FALSE(worker.settling());
  EXPECT_FALSE(worker.poll().has_value()) << "a result comes out once";

  const SolveWorkerStats stats = worker.stats();
  EXPECT_EQ(stats.cancelled, 1u) << "the held solve was abandoned for the newest request";
  EXPECT_EQ(stats.discarded, 0u);
  EXPECT_EQ(stats.solved, final_result.preview ? 2u : 1u) << "only the newest request was solved";
}

// A fast drag: a change every third of a millisecond while the worker solves. Results come out newest-last and each
// once, and the last one answers the final parameters with the tables of a direct solve. (How long submit() and
// poll() take is printed, not judged: the test above shows they do not wait.)
TEST(SolveWorker, AThousandRapidChangesEndOnTheFinalParameters) {
  Publications publications;
  SolveWorker worker(publications.callback());
  std::uint64_t last_generation = 0, last_seen = 0;
  int results_seen = 0;
  constexpr int kChanges = 1000;
  for (int k = 0; k < kChanges; ++k) {
    last_generation = worker.submit(request_number(k));
    if (std::optional<SolveResult> result = worker.poll()) {
      EXPECT_GT(result->generation, last_seen) << "results come out newest-last, each once";
      last_seen = result->generation;
      ++results_seen;
    }
    std::this_thread::sleep_for(300us);  // the pace of the drag, not a bound on anything
  }
  EXPECT_EQ(last_generation, static_cast<std::uint64_t>(kChanges));

  SolveResult final_result = wait_for(worker, publications, last_generation);
  if (final_result.preview) final_result = next_result(worker, publications);
  ASSERT_EQ(final_result.generation, last_generation);
  EXPECT_FALSE(final_result.preview);
  EXPECT_TRUE(same_request(final_result.request, request_number(kChanges - 1)));
  expect_solved_as_directly(final_result);
  EXPECT_FALSE(worker.busy());
  EXPECT_FALSE(worker.settling());
  EXPECT_FALSE(worker.poll().has_value()) << "a result comes out once";

  const SolveWorkerStats stats = worker.stats();
  std::printf(
      "[ worker  ] %d submits: %llu solves, %llu cancelled, %llu stale results discarded, %d intermediate "
      "results polled\n",
      kChanges, static_cast<unsigned long long>(stats.solved), static_cast<unsigned long long>(stats.cancelled),
      static_cast<unsigned long long>(stats.discarded), results_seen);
}

// A request superseded while its solve runs never comes out: the first request's solve is held until the second
// has been submitted.
TEST(SolveWorker, ASupersededRequestNeverComesOut) {
  Publications publications;
  HeldFirstSolve held;
  SolveWorker worker(publications.callback(), held.function());
  const std::uint64_t first = worker.submit(request_number(0));
  held.wait_until_entered();
  const std::uint64_t second = worker.submit(request_number(1));
  ASSERT_GT(second, first);
  held.release();
  const SolveResult result = wait_for(worker, publications, second);  // fails on any result of `first`
  EXPECT_EQ(result.generation, second);
  EXPECT_TRUE(same_request(result.request, request_number(1)));
}

TEST(SolveWorker, ACostlyMaterialShowsAPreviewThenSettlesOnTheFullSolve) {
  SolveRequest request = request_number(3);
  request.material.layer.sigma = 0.15;  // N 44 and 161 interface azimuths at full resolution
  ASSERT_TRUE(preview_is_coarser(request.material.layer));
  Publications publications;
  HeldFirstSolve held(HeldFirstSolve::Phase::Full);  // until the preview is polled: poll() gives the newest only
  SolveWorker worker(publications.callback(), held.function());
  const std::uint64_t generation = worker.submit(request);
  const SolveResult preview = next_result(worker, publications);
  EXPECT_EQ(preview.generation, generation);
  EXPECT_TRUE(preview.preview) << "the quick look comes first";
  EXPECT_EQ(preview.error, "");
  held.wait_until_entered();
  held.release();
  const SolveResult final_result = next_result(worker, publications);
  EXPECT_EQ(final_result.generation, generation);
  EXPECT_FALSE(final_result.preview);
  EXPECT_FALSE(worker.settling());
  EXPECT_FALSE(worker.poll().has_value()) << "two results for one request, each once";
  expect_same_tables(final_result.tables(), solve_color(request.material, request.theta_i));
  const SolveWorkerStats stats = worker.stats();
  EXPECT_EQ(stats.previews, 1u);
  EXPECT_EQ(stats.solved, 2u);
}

// Newer parameters submitted while a preview's refinement (its full solve, held here) runs: the refinement is
// abandoned at its first check and never comes out.
TEST(SolveWorker, NewerParametersAbandonARefinement) {
  SolveRequest sharp = request_number(4);
  sharp.material.layer.sigma = 0.05;  // a preview first, then the full solve
  ASSERT_TRUE(preview_is_coarser(sharp.material.layer));
  Publications publications;
  HeldFirstSolve held(HeldFirstSolve::Phase::Full);
  SolveWorker worker(publications.callback(), held.function());
  const std::uint64_t first = worker.submit(sharp);
  const SolveResult preview = next_result(worker, publications);
  ASSERT_EQ(preview.generation, first);
  ASSERT_TRUE(preview.preview);
  held.wait_until_entered();
  EXPECT_TRUE(worker.settling()) << "its full solve runs";
  EXPECT_FALSE(worker.busy()) << "newer parameters may be submitted now";
  const std::uint64_t second = worker.submit(request_number(5));
  held.release();
  const SolveResult next = next_result(worker, publications);
  EXPECT_EQ(next.generation, second) << "the first request's full solve never comes out";
  EXPECT_FALSE(next.preview);
  const SolveWorkerStats stats = worker.stats();
  EXPECT_EQ(stats.cancelled, 1u) << "the refinement was abandoned";
  EXPECT_EQ(stats.discarded, 0u);
}

// A burst: while the worker's first solve is held, four threads submit 250 requests each back to back and the owner
// polls. Each generation answers the request it was returned for, nothing comes out during the burst, and once
// released the newest of the thousand is the one request solved.
TEST(SolveWorker, TheNewestOfABurstOfAThousandRequestsWins) {
  constexpr int kThreads = 4, kPerThread = 250, kRequests = kThreads * kPerThread;
  Publications publications;
  HeldFirstSolve held;
  SolveWorker worker(publications.callback(), held.function());
  worker.submit(request_number(kRequests));  // held: the burst comes while a solve runs
  held.wait_until_entered();
  std::mutex mutex;
  std::vector<int> request_of_generation(kRequests + 2, -1);  // which request_number() got each generation
  std::atomic<int> submitters_done{0};
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
      EXPECT_FALSE(worker.poll().has_value()) << "nothing is published while the first solve is held";
    }
  }
  ASSERT_TRUE(
      std::ranges::none_of(request_of_generation.begin() + 2, request_of_generation.end(), [](int k) { return k < 0; }))
      << "every submit got its own generation, 2 to " << kRequests + 1;
  const int newest = request_of_generation.back();
  held.release();

  SolveResult final_result = wait_for(worker, publications, kRequests + 1);
  if (final_result.preview) final_result = next_result(worker, publications);
  EXPECT_TRUE(same_request(final_result.request, request_number(newest)));
  expect_solved_as_directly(final_result);
  EXPECT_FALSE(worker.busy());
  EXPECT_FALSE(worker.settling());
  EXPECT_FALSE(worker.poll().has_value());
  const SolveWorkerStats stats = worker.stats();
  EXPECT_EQ(stats.cancelled, 1u) << "the held solve was abandoned";
  EXPECT_EQ(stats.solved, stats.previews + 1) << "the newest request alone was solved";
}

// Sharp interfaces (sigma 0.05, 120 ordinates): a preview phase first, then a full solve that spends its first half
// building the interface kernels.
SolveRequest kernel_bound_request() {
  SolveRequest request = request_number(2);
  request.material.layer.sigma = 0.05;
  return request;
}

// Watches the cancellation checks of the first full (not preview) solve it is given. Its kPark-th check, which a
// cold solve asks inside its first interface kernel (one check per incident direction: core's
// SolveCancellation.TheInterfaceKernelsAskOncePerIncidentDirection), is held until the worker's own check says stop
// (a newer request, or shutdown), and answers stop. Every piece of work the solver hands its parallel-for is watched
// as well: a piece that asks again after it was told to stop has gone on working, and the probe counts it.
class CancellationProbe {
 public:
  static constexpr long kPark = 5;

  SolveFunction function() {
    return [this](const SolveRequest& request, std::uint64_t generation, const SolveOptions& options) {
      if (options.preview || watching_.exchange(true)) return compute_solve(request, generation, options);
      try {
        return compute_solve(request, generation, watch(options));
      } catch (const SolveCancelled&) {
        threw_cancelled_ = true;
        throw;
      }
    };
  }
  void wait_until_parked() { parked_.wait(); }
  bool threw_cancelled() const { return threw_cancelled_.load(); }
  long stops() const {
    const std::lock_guard lock(mutex_);
    return stops_;
  }
  long went_on() const {
    const std::lock_guard lock(mutex_);
    return went_on_;
  }

 private:
  SolveOptions watch(const SolveOptions& options) {
    SolveOptions watched = options;
    watched.cancelled = [this, inner = options.cancelled] { return ask(inner); };
    watched.parallel_for = [this, inner = options.parallel_for](int count, const std::function<void(int)>& body) {
      run_parallel(inner, count, [this, &body](int index) {
        begin_piece();
        body(index);
      });
    };
    return watched;
  }

  void begin_piece() {
    const std::lock_guard lock(mutex_);
    told_to_stop_[std::this_thread::get_id()] = false;
  }

  bool ask(const CancelCheck& inner) {
    const std::thread::id thread = std::this_thread::get_id();
    {
      const std::lock_guard lock(mutex_);
      if (told_to_stop_[thread]) ++went_on_;
    }
    bool stop = inner();
    if (++asked_ == kPark) {
      parked_.count_down();
      while (!inner()) std::this_thread::yield();  // until the worker's own check says stop
      stop = true;
    }
    if (stop) {
      const std::lock_guard lock(mutex_);
      told_to_stop_[thread] = true;
      ++stops_;
    }
    return stop;
  }

  std::atomic<bool> watching_{false};
  std::atomic<bool> threw_cancelled_{false};
  std::atomic<long> asked_{0};
  std::latch parked_{1};
  mutable std::mutex mutex_;
  std::map<std::thread::id, bool> told_to_stop_;  // per thread: told to stop within the piece it runs now
  long stops_ = 0;
  long went_on_ = 0;
};

// Newer parameters stop a solve inside its interface kernels: the check held inside the first kernel answers stop
// once the newer request is in, the solve ends with SolveCancelled, and no piece of its work asks again after it was
// told to stop. The abandoned build leaves nothing behind: the same request solved again through the worker's cache
// is the cold solve exactly.
TEST(SolveWorker, ANewerRequestStopsASolveInsideItsInterfaceKernels) {
  const SolveRequest slow = kernel_bound_request();
  ASSERT_TRUE(preview_is_coarser(slow.material.layer));
  Publications publications;
  CancellationProbe probe;
  SolveWorker worker(publications.callback(), probe.function());
  const std::uint64_t first = worker.submit(slow);
  probe.wait_until_parked();
  const std::uint64_t generation = worker.submit(request_number(7));
  const SolveResult result = wait_for(worker, publications, generation);  // fails on a full result of the slow one
  EXPECT_EQ(result.generation, generation);
  EXPECT_GT(generation, first);
  EXPECT_TRUE(probe.threw_cancelled());
  EXPECT_GE(probe.stops(), 1);
  EXPECT_EQ(probe.went_on(), 0) << "a piece of the solve asked again after it was told to stop";
  EXPECT_EQ(worker.stats().cancelled, 1u);

  SolveResult resolved = wait_for(worker, publications, worker.submit(slow));
  if (resolved.preview) resolved = next_result(worker, publications);
  ASSERT_FALSE(resolved.preview);
  expect_solved_as_directly(resolved);
}

// Shutdown inside the kernels stops them at their next check rather than waiting for the build to end.
TEST(SolveWorker, DestroyingItInsideTheInterfaceKernelsStopsThem) {
  CancellationProbe probe;
  {
    SolveWorker worker({}, probe.function());
    worker.submit(kernel_bound_request());
    probe.wait_until_parked();
  }  // requests stop and joins
  EXPECT_TRUE(probe.threw_cancelled());
  EXPECT_GE(probe.stops(), 1);
  EXPECT_EQ(probe.went_on(), 0) << "a piece of the solve asked again after it was told to stop";
}

TEST(SolveWorker, AnInvalidMaterialComesBackAsAnError) {
  Publications publications;
  SolveWorker worker(publications.callback());
  SolveRequest request;
  request.material.layer.sigma = 7.0;
  const std::uint64_t generation = worker.submit(request);
  const SolveResult result = wait_for(worker, publications, generation);
  EXPECT_NE(result.error.find("sigma"), std::string::npos) << result.error;
  EXPECT_EQ(result.textures().modes, 0);
}

TEST(SolveWorker, PublishingWakesTheOwnerOncePerResult) {
  Publications publications;
  {
    SolveWorker worker(publications.callback());
    const std::uint64_t generation = worker.submit(SolveRequest{});
    wait_for(worker, publications, generation);
  }
  EXPECT_EQ(publications.count(), 1u);
}

// Destroyed with one solve in flight and another pending: it returns (a deadlock would run into ctest's timeout).
TEST(SolveWorker, DestroyingItDuringASolveReturns) {
  HeldFirstSolve held;
  {
    SolveWorker worker({}, held.function());
    worker.submit(request_number(5));
    held.wait_until_entered();
    worker.submit(request_number(6));  // pending while the first is held: dropped at shutdown
    held.release();
  }
  EXPECT_TRUE(held.solve_returned()) << "the held solve ran to its end or to its next check before the join";
}

}  // namespace
}  // namespace skinlayer
