// weighted_sum against the definition: the sum's BRDF and BTDF at arbitrary directions are the weighted sums of the
// tables' values (where no clamp binds), for tables of different mode counts; and what cannot be summed is refused.
#include "core/series/weighted_tables.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/solver.h"

namespace skinlayer {
namespace {

TEST(WeightedTables, TheSumEvaluatesToTheWeightedSumOfTheValues) {
  // Three solves of one grid size with different albedos and g (and so different mode counts); no unscattered light
  // (semi-infinite). Positive weights: the scattered values are >= 0 and no clamp binds on either side.
  std::vector<LayerTables> tables;
  SolveOptions options;
  options.table_size = 24;
  for (const auto& [albedo, g] : {std::pair{0.9, 0.8}, std::pair{0.5, 0.3}, std::pair{0.99, 0.0}}) {
    Material m;
    m.tau = std::numeric_limits<double>::infinity();
    m.albedo = albedo;
    m.g = g;
    tables.push_back(solve(m, options));
  }
  ASSERT_NE(tables[0].modes(), tables[2].modes());
  const std::vector<double> weights = {0.25, 1.5, 0.125};
  const LayerTables sum = weighted_sum(tables, weights);
  EXPECT_EQ(sum.grid_size(), 24);
  EXPECT_EQ(sum.modes(), std::max({tables[0].modes(), tables[1].modes(), tables[2].modes()}));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> polar(0.0, 1.55), azimuth(0.0, 6.283);
  for (int n = 0; n < 200; ++n) {
    const double ti = polar(random), to = polar(random), phi = azimuth(random);
    double expected = 0.0;
    for (std::size_t k = 0; k < tables.size(); ++k) expected += weights[k] * tables[k].brdf_subsurface(ti, to, phi);
    EXPECT_NEAR(sum.brdf_subsurface(ti, to, phi), expected, 1e-12 * expected + 1e-15) << ti << " " << to << " " << phi;
    for (int m = 0; m < sum.modes(); ++m) {
      double mode = 0.0;
      for (std::size_t k = 0; k < tables.size(); ++k) {
        if (m < tables[k].modes()) mode += weights[k] * tables[k].reflection_mode(m, ti, to);
      }
      EXPECT_NEAR(sum.reflection_mode(m, ti, to), mode, 1e-13);
    }
  }
}

TEST(WeightedTables, RefusesMismatchedGridsWeightsAndUnscatteredLight) {
  Material semi_infinite;
  semi_infinite.tau = std::numeric_limits<double>::infinity();
  SolveOptions small, large;
  small.table_size = 16;
  large.table_size = 20;
  const std::vector<LayerTables> mismatched = {solve(semi_infinite, small), solve(semi_infinite, large)};
  EXPECT_THROW(weighted_sum(mismatched, std::vector<double>{0.5, 0.5}), std::invalid_argument);
  EXPECT_THROW(weighted_sum(std::vector<LayerTables>{mismatched[0]}, std::vector<double>{0.5, 0.5}),
               std::invalid_argument);
  EXPECT_THROW(weighted_sum(std::vector<LayerTables>{}, std::vector<double>{}), std::invalid_argument);
  Material thin;  // the paper's default: a finite layer under rough interfaces carries unscattered light
  thin.tau = 0.5;
  Material thick = thin;
  thick.tau = 1.0;
  ASSERT_NE(solve(thin, small).unscattered().path(), UnscatteredPath::None);
  EXPECT_THROW(weighted_sum(std::vector<LayerTables>{solve(thin, small), solve(thick, small)},
                            std::vector<double>{0.5, 0.5}),
               std::invalid_argument);
}

// One unscattered light in every table (a rough top's multiply scattered reflection does not depend on the albedo)
// adds up: the sum carries it weighted by the sum of the weights.
TEST(WeightedTables, TheSameUnscatteredLightAddsUpByItsWeights) {
  Material dark;
  dark.tau = std::numeric_limits<double>::infinity();
  dark.albedo = 0.3;
  Material bright = dark;
  bright.albedo = 0.9;
  const std::vector<LayerTables> tables = {solve(dark), solve(bright)};
  ASSERT_TRUE(tables[0].unscattered().reflects());  // the default interfaces scatter more than once
  const LayerTables sum = weighted_sum(tables, std::vector<double>{0.3, 0.5});
  EXPECT_DOUBLE_EQ(sum.unscattered().weight(), 0.8);
  const double one = tables[0].unscattered().brdf(0.7, 1.1, 2.5);
  ASSERT_GT(one, 0.0);
  EXPECT_NEAR(sum.unscattered().brdf(0.7, 1.1, 2.5), 0.8 * one, 1e-12 * one);
}

}  // namespace
}  // namespace skinlayer
