// The subsurface radius a fitted shader carries (issue 44): how far light goes under the surface, per RGB channel,
// which the BRDF does not show but a renderer's subsurface scattering needs. Taken from the material's mean free path
// 1 / mu_t: that of its deepest layer, where the light that diffuses back spends most of its path (a skin's dermis,
// a single layer's own). A colour channel mixes its solves' mean free paths with the channel's weights where they are
// positive (a skin's spectrum: its linear-sRGB weights under D65; app/material/color_channels.h). Renderers that
// take a radius (Blender's random walk, OpenPBR's subsurface_radius) read it as this mean free path.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "app/material/material_document.h"

namespace skinlayer {

struct SubsurfaceRadius {
  std::optional<Eigen::Array3d> millimetres;  // per channel; unset where the material has no physical length
  std::string source;                         // what it was taken from, or why there is none (one sentence)
};

SubsurfaceRadius subsurface_radius(const MaterialDocument& document);

}  // namespace skinlayer
