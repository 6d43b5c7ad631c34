#include "app/solution/subsurface_radius.h"

#include <algorithm>

#include "app/material/color_channels.h"

namespace skinlayer {
namespace {

// The deepest layer's extinction, 1/mm, where the material gives it.
std::optional<double> deepest_extinction(const Material& material) {
  if (material.below.empty()) return material.extinction;
  return material.below.back().extinction;
}

}  // namespace

SubsurfaceRadius subsurface_radius(const MaterialDocument& document) {
  const ColorChannels channels = color_channels(document);
  Eigen::Array3d weighted = Eigen::Array3d::Zero(), weights = Eigen::Array3d::Zero();
  for (std::size_t k = 0; k < channels.materials.size(); ++k) {
    const std::optional<double> extinction = deepest_extinction(channels.materials[k]);
    if (!extinction || !(*extinction > 0.0)) {
      return {std::nullopt,
              "none: the material has no physical length (give its deepest layer's extinction mu_t in 1/mm)"};
    }
    for (int c = 0; c < 3; ++c) {
      const double w = std::max(0.0, channels.to_rgb(c, static_cast<Eigen::Index>(k)));
      weighted(c) += w / *extinction;
      weights(c) += w;
    }
  }
  return {weighted / weights, document.skin ? "mean free path 1/mu_t of the dermis, per channel through the spectrum"
                                            : "mean free path 1/mu_t of the deepest layer"};
}

}  // namespace skinlayer
