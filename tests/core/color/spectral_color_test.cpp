// Colour from spectra (core/color/spectral_color.h) against the facts it must reproduce: the tables' check values,
// D65's published white point, white in -> white out, and the sRGB transfer function's published constants.
#include "core/color/spectral_color.h"

#include <gtest/gtest.h>

#include <Eigen/LU>  // Matrix::inverse
#include <vector>

#include "core/color/luminance.h"
#include "core/data/embedded_table.h"
#include "core/skin/skin_optics.h"

namespace skinlayer {
namespace {

TEST(EmbeddedTables, HoldThePublishedCheckValues) {
  const data::EmbeddedTable cmf = data::cie1931_2deg_cmf();
  EXPECT_EQ(cmf.rows(), 471);
  EXPECT_DOUBLE_EQ(cmf.interpolate(2, 555.0), 1.0);  // ybar's maximum
  EXPECT_NEAR(cmf.interpolate(1, 600.0), 1.0622, 1e-4);
  EXPECT_NEAR(cmf.interpolate(3, 450.0), 1.77211, 1e-5);
  const data::EmbeddedTable d65 = data::cie_d65();
  EXPECT_EQ(d65.rows(), 531);
  EXPECT_DOUBLE_EQ(d65.interpolate(1, 560.0), 100.0);
  EXPECT_NEAR(d65.interpolate(1, 419.0), 93.2372, 1e-9);
  const data::EmbeddedTable hb = data::hemoglobin_prahl();
  EXPECT_EQ(hb.rows(), 376);
  EXPECT_DOUBLE_EQ(hb.interpolate(1, 414.0), 524280.0);  // the Soret peak of HbO2
  EXPECT_DOUBLE_EQ(hb.interpolate(2, 560.0), 53788.0);
  EXPECT_NEAR(hb.interpolate(1, 577.0), 55134.0, 1.0);  // between the 576 and 578 nm rows
}

TEST(SpectralColor, D65WhitePointIsThePublishedOne) {
  const Eigen::Vector3d white = d65_white_xyz();
  const double sum = white.sum();
  EXPECT_NEAR(white.x() / sum, 0.31273, 5e-5);
  EXPECT_NEAR(white.y() / sum, 0.32902, 5e-5);
  EXPECT_NEAR(white.z(), 1.08883, 1e-4);
}

TEST(SpectralColor, TheMatrixIsTheStandardSrgbOne) {
  // IEC 61966-2-1's matrix, printed to four decimals.
  Eigen::Matrix3d standard;
  standard << 3.2406, -1.5372, -0.4986, -0.9689, 1.8758, 0.0415, 0.0557, -0.2040, 1.0570;
  EXPECT_LT((xyz_to_linear_srgb() - standard).cwiseAbs().maxCoeff(), 1.5e-3);
}

// core/color/luminance.h's weights are the Y row of the inverse of that matrix (linear sRGB to XYZ) to the four
// decimals the standard prints (cut, not rounded: 0.2126 for 0.21267), and a white RGB has luminance 1.
TEST(SpectralColor, TheLuminanceWeightsAreTheYRowOfTheSrgbMatrix) {
  const Eigen::Matrix3d to_xyz = xyz_to_linear_srgb().inverse();
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(kRec709Luminance[c], to_xyz(1, c), 1e-4) << c;
  EXPECT_DOUBLE_EQ(luminance(1.0, 1.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(luminance(0.0, 2.0, 0.0), 2.0 * 0.7152);
}

TEST(SpectralColor, APerfectWhiteReflectorIsWhiteOnAnyGrid) {
  for (const std::vector<double>& grid :
       {wavelength_grid(400, 700, 10), wavelength_grid(400, 700, 30), wavelength_grid(380, 780, 5), {550.0}}) {
    const Eigen::Matrix<double, 3, Eigen::Dynamic> w = linear_srgb_weights(grid);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(w.row(c).sum(), 1.0, 1e-12) << grid.size();
  }
}

TEST(SpectralColor, ALongWavePassIsRedAndAShortWavePassIsBlue) {
  const std::vector<double> grid = wavelength_grid(400, 700, 10);
  const Eigen::Matrix<double, 3, Eigen::Dynamic> w = linear_srgb_weights(grid);
  Eigen::VectorXd red(grid.size()), blue(grid.size());
  for (std::size_t k = 0; k < grid.size(); ++k) {
    red(static_cast<Eigen::Index>(k)) = grid[k] >= 600 ? 1.0 : 0.0;
    blue(static_cast<Eigen::Index>(k)) = grid[k] <= 480 ? 1.0 : 0.0;
  }
  const Eigen::Vector3d r = w * red, b = w * blue;
  EXPECT_GT(r(0), 2.0 * r(1));
  EXPECT_GT(r(0), 2.0 * r(2));
  EXPECT_GT(b(2), 2.0 * b(0));
  EXPECT_GT(b(2), b(1));
}

TEST(SpectralColor, TransferFunctionRoundTripsAndHasTheStandardConstants) {
  EXPECT_DOUBLE_EQ(srgb_encode(0.0), 0.0);
  EXPECT_NEAR(srgb_encode(1.0), 1.0, 1e-12);
  EXPECT_NEAR(srgb_encode(0.0031308), 0.04045, 1e-6);  // the two pieces meet
  EXPECT_NEAR(srgb_encode(0.18), 0.4614, 1e-4);        // middle grey
  for (double v : {0.0, 0.001, 0.01, 0.2, 0.5, 0.9, 1.0}) EXPECT_NEAR(srgb_decode(srgb_encode(v)), v, 1e-12);
}

}  // namespace
}  // namespace skinlayer
