// The spectral skin's figures (issue 25): reflectance spectra as one skin parameter varies, and a row of lit spheres
// of skins. Each writes NAME.png and NAME.csv, whose rows `skinlayer spectrum` and `skinlayer albedo` reproduce:
//   SkinSpectra: curve,parameter,value,theta_i,wavelength_nm,reflectance,skin,sigma,eta (one row per wavelength,
//     400-700 nm in 5 nm steps; reflectance is the directional-hemispherical one, surface and subsurface);
//   SkinSpheres: curve,parameter,value,theta_i,reflectance_r,reflectance_g,reflectance_b,skin,sigma,eta (the
//     colour at normal incidence in linear sRGB, the sphere's centre under a white furnace).
// `skin` is the --skin value with ';' for ','.
#pragma once

#include <filesystem>

#include "app/figures/figure_builder.h"
#include "app/figures/figure_set.h"
#include "app/figures/font.h"

namespace skinlayer::figures {

// spec.kind is SkinSpectra or SkinSpheres; every curve has a skin. `size`: the figure's height scale in pixels.
FigureSize build_skin_figure(const FigureSpec& spec, const std::filesystem::path& dir, const Font& font, int size);

}  // namespace skinlayer::figures
