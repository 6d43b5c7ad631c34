#include "app/preview/solve_worker.h"

#include <chrono>
#include <exception>
#include <utility>

#include "app/process/parallel_for.h"
#include "app/render/scene.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer {

SolveResult compute_solve(const SolveRequest& request, std::uint64_t generation, const SolveOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SolveResult result;
  result.generation = generation;
  result.request = request;
  result.preview = options.preview;
  try {
    const std::array<bool, 3> needed = needed_models(request);
    for (std::size_t m = 0; m < needed.size(); ++m) {
      if (!needed[m]) continue;
      ColorMaterial material = request.material;
      material.model = static_cast<SubsurfaceModel>(m);
      result.by_model[m] = solve_color(material, request.theta_i, options);
      result.textures_by_model[m] = make_table_textures(*result.by_model[m]);
    }
  } catch (const SolveCancelled&) {
    throw;
  } catch (const std::exception& error) {
    result.preview = false;  // an error is final: the full solve would fail the same way
    result.by_model = {};
    result.by_model[static_cast<std::size_t>(request.material.model)].emplace();
    result.textures_by_model = {};
    result.error = error.what();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

namespace {

// Whether the request gets a preview phase; an invalid material does not (its full solve reports the error). A
// skin always does: its preview solves fewer wavelengths (skin_preview_wavelengths).
bool wants_preview(const SolveRequest& request) {
  try {
    if (request.material.skin) {
      validate(*request.material.skin);
      return true;
    }
    return preview_is_coarser(request.material.layer);
  } catch (const ParameterError&) {
    return false;
  }
}

}  // namespace

SolveWorker::SolveWorker(std::function<void()> on_published, SolveFunction solve)
    : on_published_(std::move(on_published)),
      solve_(std::move(solve)),
      thread_([this](std::stop_token stop) { run(std::move(stop)); }) {}

std::uint64_t SolveWorker::submit(SolveRequest request) {
  std::optional<SolveRequest> replaced;  // destroyed after the lock is released
  std::uint64_t generation = 0;
  {
    const std::lock_guard lock(mutex_);
    replaced = std::exchange(pending_, std::move(request));
    generation = ++submitted_;
  }
  wake_.notify_one();
  return generation;
}

std::optional<SolveResult> SolveWorker::poll() {
  const std::lock_guard lock(mutex_);
  return std::exchange(finished_, std::nullopt);
}

bool SolveWorker::busy() const {
  const std::lock_guard lock(mutex_);
  return published_ < submitted_;
}

bool SolveWorker::settling() const {
  const std::lock_guard lock(mutex_);
  return settled_ < submitted_;
}

SolveWorkerStats SolveWorker::stats() const {
  const std::lock_guard lock(mutex_);
  return stats_;
}

bool SolveWorker::superseded(std::uint64_t generation, const std::stop_token& stop) const {
  if (stop.stop_requested()) return true;
  const std::lock_guard lock(mutex_);
  return generation != submitted_;
}

bool SolveWorker::publish(SolveResult&& result, bool final_result) {
  std::optional<SolveResult> dropped;  // a stale or unpolled result, freed after the lock is released
  {
    const std::lock_guard lock(mutex_);
    ++stats_.solved;
    if (result.generation != submitted_) {
      ++stats_.discarded;  // superseded after its last cancellation point; the newer request is pending
      return false;
    }
    published_ = result.generation;
    if (final_result) settled_ = result.generation;
    if (!final_result) ++stats_.previews;
    dropped = std::exchange(finished_, std::move(result));
  }
  if (on_published_) on_published_();
  return true;
}

void SolveWorker::run(std::stop_token stop) {
  while (true) {
    SolveRequest request;
    std::uint64_t generation = 0;
    {
      std::unique_lock lock(mutex_);
      if (!wake_.wait(lock, stop, [this] { return pending_.has_value(); }) || stop.stop_requested()) return;
      request = std::move(*pending_);
      pending_.reset();
      generation = submitted_;
    }
    SolveOptions options;
    options.cache = &cache_;
    options.parallel_for = parallel_for_threads;
    options.cancelled = [this, generation, &stop] { return superseded(generation, stop); };
    try {
      if (wants_preview(request)) {
        options.preview = true;
        SolveResult preview = solve_(request, generation, options);
        const bool failed = !preview.error.empty();
        if (!publish(std::move(preview), failed) || failed) continue;
        if (superseded(generation, stop)) {  // newer parameters came with the preview: its refinement is abandoned
          const std::lock_guard lock(mutex_);
          ++stats_.cancelled;
          continue;
        }
        options.preview = false;
      }
      publish(solve_(request, generation, options), true);
    } catch (const SolveCancelled&) {
      const std::lock_guard lock(mutex_);
      ++stats_.cancelled;
    }
    const std::lock_guard lock(mutex_);
    stats_.cache_bytes = cache_.bytes();
  }
}

}  // namespace skinlayer
