// What a shader fit loses, as a picture: the material's sphere, the fitted shader's sphere and the map of their
// difference, side by side (issue 44; `skinlayer fit --picture FILE.png`). Drawn on the CPU from the BSDFs
// themselves, the same way for both: an orthographic view of a unit sphere lit by a directional light of irradiance
// pi 45 degrees from the view, from the left (as `skinlayer render` draws it), so a pixel's radiance is
// pi f(l, v) cos(theta_l) in linear sRGB, shown through the tone map 1 - exp(-L) and the sRGB curve. The map shows the
// relative difference of the luminance, fitted over exact minus 1, from blue (-25% or less) through white to red
// (+25% or more), where the exact sphere is brighter than 1% of its brightest pixel.
#pragma once

#include <functional>
#include <string>

#include "app/figures/font.h"
#include "app/material/material_document.h"
#include "app/render/png_export.h"
#include "core/interfaces/microfacet.h"
#include "core/parallel_for.h"

namespace skinlayer::figures {

using FittedBrdf = std::function<Eigen::Array3d(const Vec3& omega_i, const Vec3& omega_o)>;  // f cos(theta_i)

struct FitComparison {
  Image image;
  double rms_difference = 0.0;  // of the map's relative differences over its pixels
  double lit_pixels = 0;
};

// `fitted_label` names the shader ("Blender Principled", "OpenPBR Surface"); sphere_size is each sphere's side.
FitComparison draw_fit_comparison(const MaterialDocument& document, const FittedBrdf& fitted,
                                  const std::string& fitted_label, const Font& font, int sphere_size,
                                  const ParallelFor& parallel_for);

}  // namespace skinlayer::figures
