// CIELAB (CIE 1976 L*a*b*, relative to D65: core/color/spectral_color.h's white) and the CIEDE2000 colour
// difference (CIE 142-2001; the formulas as Sharma, Wu & Dalal 2005 give them, "The CIEDE2000 color-difference
// formula: implementation notes, supplementary test data, and mathematical observations", Color Res. Appl. 30).
#pragma once

#include <Eigen/Core>

namespace skinlayer {

// L*a*b* of linear sRGB (the sRGB matrix's inverse, then CIE 1976 with the D65 white at Y = 1).
Eigen::Vector3d linear_srgb_to_lab(const Eigen::Vector3d& rgb);
// L*a*b* of XYZ relative to the white `white` (Y of the white = 1 scale).
Eigen::Vector3d xyz_to_lab(const Eigen::Vector3d& xyz, const Eigen::Vector3d& white);

// Delta E_00 between two L*a*b* colours, with k_L = k_C = k_H = 1.
double ciede2000(const Eigen::Vector3d& lab1, const Eigen::Vector3d& lab2);

}  // namespace skinlayer
