// The luminance Y of linear sRGB: the middle row of IEC 61966-2-1's RGB-to-XYZ matrix (Rec. 709 primaries, D65
// white), Y = 0.2126 R + 0.7152 G + 0.0722 B. Dimensionless weights that sum to 1, so a white RGB has Y = 1 and
// Y carries the units of the values it weighs (radiance, a BSDF in 1/sr).
#pragma once

#include <array>

namespace skinlayer {

inline constexpr std::array<double, 3> kRec709Luminance = {0.2126, 0.7152, 0.0722};

inline constexpr double luminance(double red, double green, double blue) {
  return kRec709Luminance[0] * red + kRec709Luminance[1] * green + kRec709Luminance[2] * blue;
}

}  // namespace skinlayer
