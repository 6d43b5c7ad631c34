// The subsurface scattering a fitted shader carries (issue 44): how far light goes under the surface, per RGB
// channel, which the BRDF does not show but a renderer's subsurface scattering needs. Taken from the material's
// deepest layer, where the light that diffuses back spends most of its path (a skin's dermis, a single layer's own):
// its mean free path 1 / mu_t and its Henyey-Greenstein g. A colour channel mixes its solves' values with the
// channel's weights where they are positive (a skin's spectrum: its linear-sRGB weights under D65;
// app/material/color_channels.h).
//   OpenPBR's subsurface_radius is the mean free path, and subsurface_scatter_anisotropy g (its specification);
//   Blender 3.4's random walk reads its radius d as sigma_t = 1 / (d (1 - g)) with g its Subsurface Anisotropy
//   (Cycles' integrator/subsurface_random_walk.h), so its radius is 1 / ((1 - g) mu_t), the reduced mean free path.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "app/material/material_document.h"

namespace skinlayer {

struct SubsurfaceScattering {
  std::optional<Eigen::Array3d> mean_free_path_mm;     // per channel; unset where the material has no physical length
  Eigen::Array3d anisotropy = Eigen::Array3d::Zero();  // the deepest layer's g, per channel
  std::string source;                                  // what it was taken from, or why there is none (one sentence)
};

SubsurfaceScattering subsurface_scattering(const MaterialDocument& document);

}  // namespace skinlayer
