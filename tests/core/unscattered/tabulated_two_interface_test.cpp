// The tabulated two-interface unscattered BTDF (core/unscattered/tabulated_two_interface.h) against the pointwise
// slope-space quadrature it stands in for (UnscatteredLight::btdf), at random direction pairs and at the lobes'
// peaks, where a spline of a narrow lobe errs first.
#include "core/unscattered/tabulated_two_interface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/conventions.h"
#include "core/material.h"

namespace skinlayer {
namespace {

struct Case {
  const char* name;
  Material material;
  double max_theta_o;  // radians; past it the pointwise rule is not the reference (two_interface_series_test.cpp)
};

std::vector<Case> cases() {
  Material fine;  // both interfaces at the smallest sigma tabulated
  fine.sigma = kMinTabulatedSigma;
  Material rough;
  rough.sigma = 1.0;
  Material mixed;  // a sharper bottom into a denser medium, thinner layer
  mixed.bottom.sigma = 0.2;
  mixed.bottom.eta = 1.3;
  mixed.tau = 0.3;
  Material stacked;  // open top, an interface between layers and a rough bottom: depths before and after the path
  stacked.eta = 1.0;
  stacked.tau = 0.4;
  stacked.below.push_back(StackedLayer{0.5, 0.9, 0.5, LayerInterface{0.4, 1.5}});
  stacked.bottom.sigma = 0.4;
  stacked.bottom.eta = 1.5;
  return {{"default", Material{}, 1.5},
          {"sigma 0.15", fine, 1.5},
          {"sigma 1", rough, 1.5},
          {"sharper bottom", mixed, 1.1},
          {"stack", stacked, 1.5}};
}

// The lobe's peak at theta_i: the straight-through exit, forward.
double peak(const UnscatteredLight& light, double theta_i) {
  return light.btdf(theta_i, light.straight_through_angle(theta_i), kPi);
}

TEST(TabulatedTwoInterfaceBtdf, MatchesTheQuadratureAtPointsAndPeaks) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const Case& c : cases()) {
    const UnscatteredLight light(c.material);
    ASSERT_TRUE(TabulatedTwoInterfaceBtdf::can_tabulate(light)) << c.name;
    const TabulatedTwoInterfaceBtdf table(light);
    double worst_point = 0.0, worst_peak = 0.0, worst_grazing = 0.0;
    for (int n = 0; n < 600; ++n) {
      const double theta_i = degrees_to_radians(89.0) * unit(random);
      const double top = peak(light, theta_i);
      const double straight = light.straight_through_angle(theta_i);
      // A third at the peak, a third beside it (within ~2 lobe widths), a third anywhere.
      double theta_o = straight, phi = kPi;
      if (n % 3 == 1) {
        theta_o = std::clamp(straight + 0.3 * (unit(random) - 0.5), 0.0, c.max_theta_o);
        phi = kPi + 0.6 * (unit(random) - 0.5);
      } else if (n % 3 == 2) {
        theta_o = c.max_theta_o * unit(random);
        phi = 2.0 * kPi * unit(random);
      }
      if (theta_o > c.max_theta_o) continue;
      const double error = std::abs(table.btdf(theta_i, theta_o, phi) - light.btdf(theta_i, theta_o, phi)) / top;
      double& worst = theta_i > degrees_to_radians(85.0) ? worst_grazing : n % 3 == 0 ? worst_peak : worst_point;
      worst = std::max(worst, error);
    }
    RecordProperty(c.name, testing::PrintToString(std::vector{worst_peak, worst_point, worst_grazing}));
    std::printf("%s: peak %.2e point %.2e grazing %.2e\n", c.name, worst_peak, worst_point, worst_grazing);
    EXPECT_LT(worst_peak, 5e-3) << c.name;  // of the peak at that theta_i
    EXPECT_LT(worst_point, 5e-3) << c.name;
    EXPECT_LT(worst_grazing, 3e-2) << c.name;  // sigma 1: 2.3% with height-correlated masking, 2% separable
  }
}

TEST(TabulatedTwoInterfaceBtdf, OfferedOnlyForTwoRoughInterfacesOfSigmaAtLeastTheMinimum) {
  Material sharp;
  sharp.bottom.sigma = 0.1;
  EXPECT_FALSE(TabulatedTwoInterfaceBtdf::can_tabulate(UnscatteredLight(sharp)));
  EXPECT_THROW(TabulatedTwoInterfaceBtdf{UnscatteredLight(sharp)}, std::invalid_argument);
  Material matched;
  matched.bottom.kind = BottomKind::Matched;
  EXPECT_FALSE(TabulatedTwoInterfaceBtdf::can_tabulate(UnscatteredLight(matched)));
  EXPECT_TRUE(TabulatedTwoInterfaceBtdf::can_tabulate(UnscatteredLight(Material{})));
}

}  // namespace
}  // namespace skinlayer
