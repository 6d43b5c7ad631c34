// What a colour material solves, and how its solves add up to linear sRGB. A BSDF is linear in the values it is
// solved for, so every colour quantity (a BRDF value, an albedo) is channel c = sum_k to_rgb(c, k) value_k over the
// solved materials k:
//   an RGB document: its distinct channels (distinct_channels), each channel picking one of them (weight 1);
//   a skin document: its layers at each wavelength of a spectral grid (core/skin/skin_optics.h), weighted by the
//   spectrum's linear-sRGB weights under D65 (core/color/spectral_color.h).
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "app/material/material_document.h"
#include "core/solver.h"

namespace skinlayer {

struct ColorChannels {
  std::vector<Material> materials;                  // the solves
  std::vector<double> wavelengths_nm;               // a skin's: materials[k] is the skin at wavelengths_nm[k]
  Eigen::Matrix<double, 3, Eigen::Dynamic> to_rgb;  // 3 x materials.size()
};

// The spectral grid of a skin's colour: 400-700 nm in 10 nm steps.
std::vector<double> skin_color_wavelengths();

// The coarser grid of a skin's colour while a slider moves (the previewer's preview phase): 400-700 nm in 50 nm steps.
std::vector<double> skin_preview_wavelengths();

// The document's solves and weights (a grey document: one material, every channel its value). `preview`: a skin on
// skin_preview_wavelengths() instead of skin_color_wavelengths().
ColorChannels color_channels(const MaterialDocument& document, bool preview = false);

// One colour channel's directional albedo, sum_k weights(k) per_solve[k] field by field (each is linear in the solved
// values); the surface reflectance, the same in every solve, is per_solve[0]'s. per_solve[k] is ColorChannels'
// materials[k] at one incident angle, and weights a row of to_rgb.
DirectionalAlbedo mixed_albedo(std::span<const DirectionalAlbedo> per_solve, const Eigen::RowVectorXd& weights);

}  // namespace skinlayer
