#include "app/window/environment_preview.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "app/gl/gl_api.h"

namespace skinlayer {

std::string EnvironmentPreview::load(Renderer& renderer, const std::string& source) {
  if (source.empty() || source == loaded_) return "";
  try {
    std::optional<EnvironmentMap> map = builtin_environment(source);
    renderer.upload_environment(map ? *map : read_hdr_environment(source));
  } catch (const std::exception& error) {
    return error.what();
  }
  loaded_ = source;
  accumulation_.reset();
  return "";
}

bool EnvironmentPreview::refine(const Renderer& renderer, const Key& key, const EnvironmentView& view,
                                const SurfaceParams& surface, double budget_seconds) {
  const int width = std::max(16, key.width / kResolutionDivisor);
  const int height = std::max(16, key.height / kResolutionDivisor);
  if (!accumulation_ || !(key == key_)) {
    if (!accumulation_ || accumulation_->target().width() != width || accumulation_->target().height() != height) {
      accumulation_.emplace(width, height);
    } else {
      accumulation_->clear();
    }
    key_ = key;
    samples_per_pass_ = 1;
    // The first frame after a change shows one sample per pixel and nothing more, so that it comes about as soon as
    // the directional light's frame (bench_render: BM_EnvironmentChangeLatency).
    renderer.accumulate_environment(*accumulation_, view, surface, 1, key.slot);
    return true;
  }
  if (accumulation_->samples() >= kMaxSamples) return false;
  const auto start = std::chrono::steady_clock::now();
  do {
    const auto pass_start = std::chrono::steady_clock::now();
    renderer.accumulate_environment(*accumulation_, view, surface,
                                    std::min(samples_per_pass_, kMaxSamples - accumulation_->samples()), key.slot);
    glFinish();
    // Passes of about a quarter of the budget: fewer draw calls once a pass is known to be cheap.
    const double pass = std::chrono::duration<double>(std::chrono::steady_clock::now() - pass_start).count();
    if (pass < 0.25 * budget_seconds) samples_per_pass_ = std::min(samples_per_pass_ * 2, 64);
    if (pass > 0.5 * budget_seconds) samples_per_pass_ = std::max(samples_per_pass_ / 2, 1);
  } while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < budget_seconds &&
           accumulation_->samples() < kMaxSamples);
  return accumulation_->samples() < kMaxSamples;
}

}  // namespace skinlayer
