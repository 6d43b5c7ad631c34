// A profile pre-integrated over a sphere's curvature (core/spatial/curvature_spread.h): its limits and the light it
// keeps.
#include "core/spatial/curvature_spread.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/conventions.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

// An exponential profile of width w (power e^{-r/w} r dr per annulus, up to 30 w), on 200 geometric annuli.
CurvatureSpread exponential(double width, double sphere_radius) {
  std::vector<double> edges = {0.0}, powers;
  for (int i = 0; i < 200; ++i) edges.push_back(1e-3 * width * std::pow(3e4, i / 199.0));
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    const auto mass = [&](double r) { return -(r + width) * std::exp(-r / width); };  // int e^{-r/w} r dr / w
    powers.push_back(mass(edges[i + 1]) - mass(edges[i]));
  }
  return CurvatureSpread(edges, powers, sphere_radius);
}

TEST(CurvatureSpread, ANarrowProfileIsTheCosine) {
  const CurvatureSpread spread = exponential(1e-4, 1.0);
  for (const double degrees : {0.0, 30.0, 60.0, 85.0, 95.0, 120.0, 180.0}) {
    const double theta = degrees_to_radians(degrees);
    EXPECT_NEAR(spread(theta), std::max(0.0, std::cos(theta)), 1e-3) << degrees;
  }
}

// Over the sphere the spread irradiance adds up to the incident one (int D sin(theta) d theta = 1/2) whatever the
// profile's width, while a wide profile lights the night side and dims the lit pole.
TEST(CurvatureSpread, KeepsTheLightAndReachesPastTheTerminator) {
  const QuadratureRule rule = gauss_legendre(64, 0.0, kPi);
  for (const double width : {0.01, 0.1, 0.3, 1.0}) {
    const CurvatureSpread spread = exponential(width, 1.0);
    double total = 0.0;
    for (int q = 0; q < rule.size(); ++q) {
      const std::size_t k = static_cast<std::size_t>(q);
      total += rule.weights[k] * spread(rule.nodes[k]) * std::sin(rule.nodes[k]);
    }
    EXPECT_NEAR(total, 0.5, 2e-4) << width;
    EXPECT_LT(spread(0.0), 1.0) << width;
    EXPECT_GT(spread(degrees_to_radians(100.0)), 0.0) << width;
  }
  // Wider spreads more: the night side brighter, the pole darker.
  EXPECT_GT(exponential(0.3, 1.0)(degrees_to_radians(110.0)), exponential(0.1, 1.0)(degrees_to_radians(110.0)));
  EXPECT_LT(exponential(0.3, 1.0)(0.0), exponential(0.1, 1.0)(0.0));
  // A larger sphere is flatter: the same profile spreads less.
  EXPECT_LT(exponential(0.1, 10.0)(degrees_to_radians(100.0)), exponential(0.1, 1.0)(degrees_to_radians(100.0)));
}

TEST(CurvatureSpread, RefusesBadInput) {
  const double edges[] = {0.0, 1.0, 2.0};
  const double powers[] = {0.5, 0.5};
  const double negative[] = {0.5, -0.5};
  const double zero[] = {0.0, 0.0};
  EXPECT_THROW(CurvatureSpread(edges, powers, 0.0), std::invalid_argument);
  EXPECT_THROW(CurvatureSpread(edges, negative, 1.0), std::invalid_argument);
  EXPECT_THROW(CurvatureSpread(edges, zero, 1.0), std::invalid_argument);
  EXPECT_THROW(CurvatureSpread(std::span<const double>(edges, 2), powers, 1.0), std::invalid_argument);
  EXPECT_NO_THROW(CurvatureSpread(edges, powers, 0.3));  // annuli beyond the diameter are cut
}

}  // namespace
}  // namespace skinlayer
