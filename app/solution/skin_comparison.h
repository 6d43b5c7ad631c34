// The one homogeneous layer that stands for a skin in the comparison models. Lambert and Hanrahan-Krueger
// (core/models/subsurface_model.h) describe one layer, and a skin is two at every wavelength (an epidermis over a
// semi-infinite dermis, core/skin/skin_optics.h). So they take the skin's RGB per channel: the layer under the skin's
// top interface (its sigma and eta), semi-infinite, with the skin's Henyey-Greenstein g (kSkinAnisotropy), whose
// single-scattering albedo in channel c makes its reflectance at normal incidence (surface and subsurface) the
// skin's own in that channel (core/fit/albedo_color_match.h). The Lambert sphere then sends back what the skin
// does for light from the normal, channel by channel, and Hanrahan-Krueger shows that layer's single scattering.
#pragma once

#include <array>

#include "app/solution/material_solve.h"
#include "core/solve/solve_options.h"

namespace skinlayer {

struct SkinComparisonLayer {
  ColorMaterial layer;                  // an RGB single layer, model Stam (the caller sets the model)
  std::array<double, 3> reflectance{};  // the skin's reflectance at normal incidence per channel, the target
};

// Throws std::invalid_argument when `skin` is no skin (ColorMaterial::skin unset), ParameterError when it is
// invalid, SolveCancelled through options.cancelled.
SkinComparisonLayer skin_comparison_layer(const ColorMaterial& skin, const SolveOptions& options = {});

}  // namespace skinlayer
