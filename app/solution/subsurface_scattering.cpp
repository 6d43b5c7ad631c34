#include "app/solution/subsurface_scattering.h"

#include <algorithm>

#include "app/material/color_channels.h"

namespace skinlayer {
namespace {

struct Deepest {
  std::optional<double> extinction;  // 1/mm
  double g = 0.0;
};

Deepest deepest_layer(const Material& material) {
  if (material.below.empty()) return {material.extinction, material.g};
  return {material.below.back().extinction, material.below.back().g};
}

}  // namespace

SubsurfaceScattering subsurface_scattering(const MaterialDocument& document) {
  const ColorChannels channels = color_channels(document);
  Eigen::Array3d path = Eigen::Array3d::Zero(), g = Eigen::Array3d::Zero(), weights = Eigen::Array3d::Zero();
  bool physical = true;
  for (std::size_t k = 0; k < channels.materials.size(); ++k) {
    const Deepest layer = deepest_layer(channels.materials[k]);
    if (!layer.extinction || !(*layer.extinction > 0.0)) physical = false;
    for (int c = 0; c < 3; ++c) {
      const double w = std::max(0.0, channels.to_rgb(c, static_cast<Eigen::Index>(k)));
      if (physical) path(c) += w / *layer.extinction;
      g(c) += w * layer.g;
      weights(c) += w;
    }
  }
  SubsurfaceScattering result;
  result.anisotropy = g / weights;
  if (!physical) {
    result.source = "none: the material has no physical length (give its deepest layer's extinction mu_t in 1/mm)";
    return result;
  }
  result.mean_free_path_mm = path / weights;
  result.source = document.skin ? "the dermis's mean free path 1/mu_t and g, per channel through the spectrum"
                                : "the deepest layer's mean free path 1/mu_t and g";
  return result;
}

}  // namespace skinlayer
