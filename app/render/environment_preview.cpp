#include "app/render/environment_preview.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>

#include "app/gl/gl_api.h"
#include "app/render/environment_map.h"

namespace skinlayer {
namespace {

// Clears `accumulation`, or makes it anew when it has another size.
void restart(std::optional<EnvironmentAccumulation>& accumulation, int width, int height) {
  if (accumulation && accumulation->target().width() == width && accumulation->target().height() == height) {
    accumulation->clear();
  } else {
    accumulation.emplace(width, height);
  }
}

// What the renderer keeps an environment under: a built-in's name; a file's path with its size and time of change,
// so that a file changed on disk is read again; "" (not kept) when the file cannot be looked at.
std::string kept_key(const std::string& source) {
  if (std::find(kBuiltinEnvironments.begin(), kBuiltinEnvironments.end(), source) != kBuiltinEnvironments.end()) {
    return source;
  }
  std::error_code error;
  const auto size = std::filesystem::file_size(source, error);
  if (error) return "";
  const auto changed = std::filesystem::last_write_time(source, error);
  if (error) return "";
  return source + "|" + std::to_string(size) + "|" + std::to_string(changed.time_since_epoch().count());
}

}  // namespace

std::string EnvironmentPreview::load(Renderer& renderer, const std::string& source) {
  if (source.empty() || source == loaded_) return "";
  const std::string key = kept_key(source);
  if (!renderer.show_kept_environment(key)) {
    try {
      renderer.upload_environment(load_environment(source), key);
    } catch (const std::exception& error) {
      return error.what();
    }
  }
  loaded_ = source;
  reset();
  return "";
}

const EnvironmentAccumulation* EnvironmentPreview::accumulation() const {
  if (fine_ && fine_->samples() >= kFineShownFrom) return &*fine_;
  return coarse_ ? &*coarse_ : nullptr;
}

bool EnvironmentPreview::refine(const Renderer& renderer, const Key& key, const EnvironmentView& view,
                                const SurfaceParams& surface, double budget_seconds) {
  if (!fine_ || !(key == key_)) {
    restart(coarse_, std::max(8, key.width / kCoarseDivisor), std::max(8, key.height / kCoarseDivisor));
    restart(fine_, std::max(16, key.width / kResolutionDivisor), std::max(16, key.height / kResolutionDivisor));
    key_ = key;
    samples_per_pass_ = 1;
    renderer.accumulate_environment(*coarse_, view, surface, 1, key.slot);
    return true;
  }
  if (fine_->samples() >= kMaxSamples) return false;
  const auto start = std::chrono::steady_clock::now();
  do {
    const auto pass_start = std::chrono::steady_clock::now();
    renderer.accumulate_environment(*fine_, view, surface, std::min(samples_per_pass_, kMaxSamples - fine_->samples()),
                                    key.slot);
    glFinish();
    // Passes of about a quarter of the budget: fewer draw calls once a pass is known to be cheap.
    const double pass = std::chrono::duration<double>(std::chrono::steady_clock::now() - pass_start).count();
    if (pass < 0.25 * budget_seconds) samples_per_pass_ = std::min(samples_per_pass_ * 2, 64);
    if (pass > 0.5 * budget_seconds) samples_per_pass_ = std::max(samples_per_pass_ / 2, 1);
  } while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < budget_seconds &&
           fine_->samples() < kMaxSamples);
  return fine_->samples() < kMaxSamples;
}

}  // namespace skinlayer
