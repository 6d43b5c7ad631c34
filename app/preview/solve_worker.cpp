#include "app/preview/solve_worker.h"

#include "app/render/scene.h"

#include <chrono>
#include <exception>
#include <utility>

namespace skinlayer {

SolveResult compute_solve(const SolveRequest& request, std::uint64_t generation) {
  const auto start = std::chrono::steady_clock::now();
  SolveResult result;
  result.generation = generation;
  result.request = request;
  try {
    result.tables = solve_color(request.material, request.theta_i);
    result.textures = make_table_textures(result.tables);
    if (request.compare) {
      for (const SubsurfaceModel model : kCompareModels) {
        ColorMaterial compared = request.material;
        compared.model = model;
        result.comparison_textures.push_back(
            model == request.material.model ? result.textures : make_table_textures(solve_color(compared, request.theta_i)));
      }
    }
  } catch (const std::exception& error) {
    result.tables = ColorTables{};
    result.textures = TableTextureData{};
    result.comparison_textures.clear();
    result.error = error.what();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

SolveWorker::SolveWorker(std::function<void()> on_published)
    : on_published_(std::move(on_published)), thread_([this](std::stop_token stop) { run(std::move(stop)); }) {}

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

SolveWorkerStats SolveWorker::stats() const {
  const std::lock_guard lock(mutex_);
  return stats_;
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
    SolveResult result = compute_solve(request, generation);
    std::optional<SolveResult> dropped;  // a stale or unpolled result, freed after the lock is released
    bool published = false;
    {
      const std::lock_guard lock(mutex_);
      ++stats_.solved;
      if (generation == submitted_) {
        dropped = std::exchange(finished_, std::move(result));
        published_ = generation;
        published = true;
      } else {
        ++stats_.discarded;  // superseded while it was solved; the newer request is pending
      }
    }
    if (published && on_published_) on_published_();
  }
}

}  // namespace skinlayer
