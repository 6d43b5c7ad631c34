// The sigmoid uplift from RGB to a spectrum (core/color/rgb_uplift.h): grey maps to the flat spectrum of that value,
// fitted colours come back through linear_srgb_weights, the spectra are what the sigmoid says (positive, at most the
// scale, smooth), and the colour of the sigmoid itself, integrated at 1 nm with the CIE tables, agrees with the
// fit's on a fine grid.
#include "core/color/rgb_uplift.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/color/spectral_color.h"
#include "core/data/embedded_table.h"

namespace skinlayer {
namespace {

std::vector<double> grid(double from, double to, double step) {
  std::vector<double> nm;
  for (double l = from; l <= to + 1e-9; l += step) nm.push_back(l);
  return nm;
}

TEST(RgbUplift, GreyIsTheFlatSpectrumOfItsValue) {
  const RgbUplift uplift(grid(400.0, 700.0, 10.0));
  for (const double v : {1e-4, 0.18, 0.5, 1.0, 7.5}) {
    const SigmoidSpectrum s = uplift.fit({v, v, v});
    std::vector<double> r(uplift.wavelengths().size());
    uplift.values(s, r);
    for (const double value : r) EXPECT_NEAR(value, v, 1e-9 * v);
    EXPECT_LT(s.rgb_error, 1e-8);
  }
}

TEST(RgbUplift, FittedColoursComeBackThroughTheWeights) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.05, 1.0);
  for (const std::vector<double>& nm : {grid(400.0, 700.0, 10.0), grid(360.0, 830.0, 47.0)}) {
    const RgbUplift uplift(nm);
    int fitted = 0;
    for (int k = 0; k < 300; ++k) {
      const std::array<double, 3> rgb = {unit(random), unit(random), unit(random)};
      const SigmoidSpectrum s = uplift.fit(rgb);
      std::vector<double> r(nm.size());
      uplift.values(s, r);
      for (const double value : r) {
        ASSERT_GT(value, 0.0);
        ASSERT_LE(value, s.scale);
      }
      const std::array<double, 3> back = uplift.rgb_of(r);
      const double largest = std::max({rgb[0], rgb[1], rgb[2]});
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], rgb[c], 1e-6 * largest) << k << " channel " << c;
      fitted += s.rgb_error < 1e-8;
    }
    EXPECT_EQ(fitted, 300);
  }
}

TEST(RgbUplift, AWarmStartReachesTheSameSpectrum) {
  const RgbUplift uplift(grid(400.0, 700.0, 10.0));
  const SigmoidSpectrum a = uplift.fit({0.8, 0.4, 0.2});
  const SigmoidSpectrum b = uplift.fit({0.81, 0.4, 0.2}, &a.coefficients);
  const SigmoidSpectrum c = uplift.fit({0.81, 0.4, 0.2});
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(b.coefficients[k], c.coefficients[k], 1e-6 * (1.0 + std::abs(c.coefficients[k])));
}

// On a 1 nm grid the hat functions reproduce the sigmoid itself, so the fit's colour is the sigmoid's colour as the
// CIE tables integrate it directly: sum cmf D65 R / sum ybar D65, then the sRGB matrix.
TEST(RgbUplift, TheSigmoidsOwnColourAgreesOnAFineGrid) {
  const RgbUplift uplift(grid(360.0, 830.0, 5.0));
  const std::array<double, 3> rgb = {0.7, 0.35, 0.12};
  const SigmoidSpectrum s = uplift.fit(rgb);
  const data::EmbeddedTable cmf = data::cie1931_2deg_cmf(), d65 = data::cie_d65();
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  double white = 0.0;
  for (int row = 0; row < cmf.rows(); ++row) {
    const double lambda = cmf.at(row, 0), power = d65.interpolate(1, lambda);
    const double x = (lambda - 360.0) / (830.0 - 360.0),
                 z = (s.coefficients[0] * x + s.coefficients[1]) * x + s.coefficients[2];
    const double r = s.scale * (0.5 + 0.5 * z / std::sqrt(1.0 + z * z));
    xyz += r * power * Eigen::Vector3d(cmf.at(row, 1), cmf.at(row, 2), cmf.at(row, 3));
    white += power * cmf.at(row, 2);
  }
  const Eigen::Vector3d back = xyz_to_linear_srgb() * (xyz / white);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], rgb[c], 1e-3 * rgb[0]) << c;
}

TEST(RgbUplift, BlackIsZeroAndBadInputIsRefused) {
  const RgbUplift uplift(grid(400.0, 700.0, 50.0));
  const SigmoidSpectrum s = uplift.fit({0.0, 0.0, 0.0});
  std::vector<double> r(uplift.wavelengths().size(), 1.0);
  uplift.values(s, r);
  for (const double value : r) EXPECT_EQ(value, 0.0);
  EXPECT_THROW(uplift.fit({-0.1, 0.5, 0.5}), std::invalid_argument);
  EXPECT_THROW(uplift.fit({NAN, 0.5, 0.5}), std::invalid_argument);
  EXPECT_THROW(RgbUplift(grid(400.0, 450.0, 50.0)), std::invalid_argument);
}

}  // namespace
}  // namespace skinlayer
