// From a spectrum to colour: CIE 1931 2-degree XYZ under illuminant D65, then linear sRGB (IEC 61966-2-1).
//
// A reflectance known at a few wavelengths lambda_k is read as linear between them and constant beyond the ends, so
// it is sum_k R_k b_k(lambda) with hat functions b_k. Its colour is then linear in the R_k:
//   XYZ = sum_k R_k W_k,   W_k = sum_lambda cmf(lambda) D65(lambda) b_k(lambda) / sum_lambda ybar(lambda) D65(lambda)
// over the 1 nm tables (core/data/), so a perfect white reflector (R = 1) has Y = 1 and the chromaticity of D65.
// The XYZ -> linear sRGB matrix is derived from the sRGB primaries (x, y) = (0.64, 0.33), (0.30, 0.60),
// (0.15, 0.06) and that same white (SMPTE RP 177's construction), so white maps to (1, 1, 1) exactly.
#pragma once

#include <Eigen/Core>
#include <span>

namespace skinlayer {

// CIE XYZ of D65 from the tables, normalized to Y = 1.
Eigen::Vector3d d65_white_xyz();

// The XYZ -> linear sRGB matrix for the primaries above and d65_white_xyz().
Eigen::Matrix3d xyz_to_linear_srgb();

// Row c, column k: the weight of the reflectance at wavelengths[k] (ascending, nm) in linear sRGB channel c.
// Every row sums to 1 (white in, white out).
Eigen::Matrix<double, 3, Eigen::Dynamic> linear_srgb_weights(std::span<const double> wavelengths);

// The sRGB transfer function (IEC 61966-2-1) and its inverse, per channel.
double srgb_encode(double linear);
double srgb_decode(double encoded);

}  // namespace skinlayer
