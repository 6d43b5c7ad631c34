// The previewer's environment lighting: the map the renderer holds, and the progressive estimate of the shown
// sphere (app/render/renderer.h's EnvironmentAccumulation), restarted whenever what it estimates changes and
// refined a little every frame while the window is otherwise idle, so that dragging stays fluid at a few samples
// per pixel and the picture converges when the mouse stops.
//
// The estimate is kept at a quarter of the sphere view's side (128 x 128 for a 512 x 512 view; the display filters
// it up): at full resolution llvmpipe adds 10 samples per pixel per second on this machine, at a quarter about 190,
// and the centre's noise 2 s after a change is 0.3-0.6% (bench_render: BM_EnvironmentConvergence).
//
// The frame right after a change shows a coarser estimate instead: one sample per pixel at an eighth of the side,
// a quarter of the quarter-side pass's cost, so that the first environment-lit frame comes within a few ms of the
// directional light's (bench_render: BM_EnvironmentChangeLatency). Each of its pixels covers four of the finer
// estimate's, so the finer one is shown once it has kFineShownFrom samples per pixel and is no noisier.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "app/render/renderer.h"

namespace skinlayer {

class EnvironmentPreview {
 public:
  static constexpr int kResolutionDivisor = 4;
  static constexpr int kCoarseDivisor = 8;
  static constexpr int kFineShownFrom = 4;
  static constexpr int kMaxSamples = 16384;

  // Makes `source` (a built-in name or a .hdr path; empty: none) the renderer's environment if it is not already.
  // One shown before and kept by the renderer is shown again without reading it (unless the file has changed).
  // Returns the error ("" when it loaded); after an error the previous environment stays.
  std::string load(Renderer& renderer, const std::string& source);
  const std::string& loaded() const { return loaded_; }

  // What the estimate depends on besides the environment: the shown result and slot, the environment's rotation
  // and scale, the sphere view's size in pixels.
  struct Key {
    std::uint64_t generation = 0;
    int slot = 0;
    double rotation = 0.0;
    double scale = 1.0;
    int width = 0;
    int height = 0;
    bool operator==(const Key&) const = default;
  };
  // If the key changed: restarts, and takes the coarse estimate's one sample and nothing more. Otherwise adds
  // passes to the finer estimate for about budget_seconds (at least one sample). Returns true while the estimate is
  // still refining (the window should draw again soon).
  bool refine(const Renderer& renderer, const Key& key, const EnvironmentView& view, const SurfaceParams& surface,
              double budget_seconds);
  // Drops the estimate (no environment shown).
  void reset() {
    coarse_.reset();
    fine_.reset();
  }

  // The estimate to show (null when there is none) and its samples per pixel.
  const EnvironmentAccumulation* accumulation() const;
  int samples() const {
    const EnvironmentAccumulation* shown = accumulation();
    return shown ? shown->samples() : 0;
  }

 private:
  std::string loaded_;
  std::optional<EnvironmentAccumulation> coarse_;
  std::optional<EnvironmentAccumulation> fine_;
  Key key_;
  int samples_per_pass_ = 1;
};

}  // namespace skinlayer
