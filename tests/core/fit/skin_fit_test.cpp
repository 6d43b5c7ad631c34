// The skin's colour match and spectrum fit (core/fit/skin_fit.h): round trips from known parameters, an
// unreachable colour answered by the nearest reachable one, and a bounded least-squares fit that can rest on a bound.
#include "core/fit/skin_fit.h"

#include <gtest/gtest.h>

#include <random>

#include "core/color/ciede2000.h"
#include "core/fit/bounded_least_squares.h"
#include "core/skin/skin_optics.h"

namespace skinlayer {
namespace {

TEST(BoundedLeastSquares, FindsAnInteriorMinimumAndRestsOnABound) {
  // r = (p0 - 0.3, 10 (p1 - 2)) in the box [0, 1] x [0, 1]: p1 rests on its upper bound.
  const auto residuals = [](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
    r.resize(2);
    r << p(0) - 0.3, 10.0 * (p(1) - 2.0);
  };
  const BoundedFit fit =
      fit_in_box(residuals, 2, Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));
  EXPECT_NEAR(fit.parameters(0), 0.3, 1e-6);
  EXPECT_NEAR(fit.parameters(1), 1.0, 1e-4);
  EXPECT_GT(fit.evaluations, 0);
}

TEST(SkinColorMatch, RoundTripsFromRandomReachableParameters) {
  std::mt19937 random(25);
  std::uniform_real_distribution<double> melanin(0.005, 0.3), blood(0.002, 0.08), scattering(0.5, 2.5);
  for (int trial = 0; trial < 5; ++trial) {
    SkinParameters truth;
    truth.melanin = melanin(random);
    truth.blood = blood(random);
    truth.scattering = scattering(random);
    const Eigen::Vector3d target = skin_normal_color(truth, Material{});
    const SkinColorMatch match = match_skin_color(target, Material{});
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(match.color(c), target(c), 0.005 * target(c))
          << "trial " << trial << " channel " << c << ": melanin " << truth.melanin << " blood " << truth.blood
          << " scattering " << truth.scattering;
    }
    EXPECT_LT(match.delta_e, 0.2);
    EXPECT_LT(match.evaluations, 400);
  }
}

TEST(SkinColorMatch, AnUnreachableColourGivesTheNearestReachableOne) {
  const Eigen::Vector3d blue(0.05, 0.1, 0.8);
  const SkinColorMatch match = match_skin_color(blue, Material{});
  EXPECT_GT(match.delta_e, 10.0);
  EXPECT_NEAR(ciede2000(linear_srgb_to_lab(blue), linear_srgb_to_lab(match.color)), match.delta_e, 1e-9);
  // What it returns is a skin's colour: the parameters reproduce it.
  const Eigen::Vector3d again = skin_normal_color(match.skin, Material{});
  EXPECT_LT((again - match.color).cwiseAbs().maxCoeff(), 1e-12);
  // Nearer than the default skin and than the corners it could have stopped at.
  const double lab_distance = (linear_srgb_to_lab(match.color) - linear_srgb_to_lab(blue)).norm();
  for (const double m : {0.0, 0.5}) {
    SkinParameters corner;
    corner.melanin = m;
    corner.blood = 0.0;
    corner.scattering = 4.0;
    EXPECT_LE(lab_distance,
              (linear_srgb_to_lab(skin_normal_color(corner, Material{})) - linear_srgb_to_lab(blue)).norm() + 1e-6);
  }
}

TEST(SkinSpectrumFit, RecoversASpectrumOfItsOwnModel) {
  SkinParameters truth;
  truth.melanin = 0.08;
  truth.eumelanin = 0.5;
  truth.blood = 0.03;
  truth.oxygenation = 0.6;
  truth.epidermis = 0.09;
  truth.scattering = 1.4;
  const std::vector<double> grid = wavelength_grid(400.0, 700.0, 10.0);
  const double theta = 8.0 * 3.14159265358979 / 180.0;
  const std::vector<double> measured = skin_reflectance_spectrum(truth, Material{}, grid, theta);
  const SkinSpectrumFit fit = fit_skin_spectrum(grid, measured, theta, 400.0, 700.0, Material{});
  EXPECT_LT(fit.rms, 1e-3);
  EXPECT_EQ(fit.wavelengths_nm.size(), grid.size());
  // Only the range counts.
  const SkinSpectrumFit part = fit_skin_spectrum(grid, measured, theta, 500.0, 600.0, Material{});
  EXPECT_EQ(part.wavelengths_nm.front(), 500.0);
  EXPECT_LE(part.wavelengths_nm.back(), 600.0);
  EXPECT_THROW(fit_skin_spectrum(grid, measured, theta, 500.0, 540.0, Material{}), std::invalid_argument);
}

}  // namespace
}  // namespace skinlayer
