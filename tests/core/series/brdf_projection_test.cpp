// Any BRDF as the solver's tables (core/series/brdf_projection.h): a series the modes hold is reproduced at the grid
// points to round-off, and a rough Principled BSDF between them within 1% of its peak, as the splines allow.
#include "core/series/brdf_projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/conventions.h"
#include "core/targets/principled_bsdf.h"

namespace skinlayer {
namespace {

TEST(BrdfProjection, ASeriesTheModesHoldComesBackAtTheGridPoints) {
  const RgbBrdf series = [](double ti, double to, double phi) {
    const double a = 0.3 + 0.1 * std::cos(ti) * std::cos(to);
    return Eigen::Array3d(a + 0.05 * std::sin(ti) * std::sin(to) * std::cos(phi),
                          a + 0.02 * std::sin(ti) * std::sin(to) * std::cos(3.0 * phi), a);
  };
  const std::array<LayerTables, 3> tables = project_brdf(series, 12, 5, {});
  for (int i = 0; i < 12; i += 3) {
    for (int o = 0; o < 12; o += 2) {
      const double ti = LayerTables::grid_angle(i, 12), to = LayerTables::grid_angle(o, 12);
      for (const double phi : {0.0, 1.0, 2.5}) {
        const Eigen::Array3d expected = series(ti, to, phi);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(tables[static_cast<std::size_t>(c)].brdf_subsurface(ti, to, phi), expected(c), 1e-12);
        }
      }
    }
  }
  EXPECT_EQ(tables[0].btdf(0.3, 0.4, 1.0), 0.0);
}

TEST(BrdfProjection, ARoughPrincipledBsdfIsWithinOnePercentOfItsPeakBetweenTheGridPoints) {
  PrincipledParameters p;
  p.base_color = Rgb(0.6, 0.4, 0.2);
  p.roughness = 0.5;
  p.sheen = 0.5;
  const RgbBrdf brdf = [&](double ti, double to, double phi) {
    return Eigen::Array3d(
        principled_brdf(p, direction_from_angles(std::min(ti, 1.57), 0.0), direction_from_angles(to, phi)));
  };
  const std::array<LayerTables, 3> tables = project_brdf(brdf, 48, 48, {});
  std::mt19937 random(3);
  std::uniform_real_distribution<double> theta(0.0, degrees_to_radians(80.0)), phi(0.0, 2.0 * kPi);
  double peak = 0.0, worst = 0.0;
  for (int k = 0; k < 400; ++k) {
    const double ti = theta(random), to = theta(random), ph = phi(random);
    const double exact = brdf(ti, to, ph)(0);
    peak = std::max(peak, exact);
    worst = std::max(worst, std::abs(tables[0].brdf_subsurface(ti, to, ph) - exact));
  }
  std::printf("  worst %.2e of a peak %.3f\n", worst, peak);
  EXPECT_LT(worst, 0.01 * peak);
}

}  // namespace
}  // namespace skinlayer
