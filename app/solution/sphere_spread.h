// The sphere's translucency: the material's reflectance profile, in mm, pre-integrated over a sphere of a given
// radius (core/spatial/curvature_spread.h, docs/model.md §21.13) into the texture the sphere shader reads. The
// profile is the costly part and does not depend on the radius, so a radius slider only redoes the cheap second step.
#pragma once

#include <vector>

#include "app/material/material_document.h"
#include "core/parallel_for.h"

namespace skinlayer {

struct SpreadProfile {
  std::vector<double> edges_mm;               // annuli about the entry point, from 0
  std::vector<std::vector<double>> power;     // [channel r, g, b][annulus]: light leaving per unit incident power
  std::vector<std::vector<double>> per_area;  // the same per unit area (1/mm^2): the profile plot's values
};

// The document's reflectance profile at normal incidence on 64 annuli out to 20 mm (the first 2 um wide, then
// geometric), at the spread's resolution: 8 nodes, 12 modes and 32 frequencies, within 0.5% of the command's to
// 1 mm and 3% at 4 mm (a skin's). A skin takes its 7 preview wavelengths with `preview`. Throws ParameterError,
// naming what it cannot take, for a material without a profile (document_profile.h) or without lengths (mu_t).
SpreadProfile spread_profile(const MaterialDocument& document, bool preview = false,
                             const ParallelFor& parallel_for = {});

// D(theta) per channel at theta_k = pi k / (samples - 1), RGB interleaved, for a sphere of radius sphere_radius_mm
// (> 0): Renderer::upload_spread's texels.
std::vector<float> spread_texture(const SpreadProfile& profile, double sphere_radius_mm, int samples = 256);

}  // namespace skinlayer
