// Cycles' sheen (docs/model.md §22.1.1): the table is read along the axes Cycles reads it, the LTC it holds is a
// density over the light, and it is the table the paper's analytic fit approximates.
#include "core/targets/cycles_sheen.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/targets/zeltner_fuzz.h"
#include "tests/core/targets/hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::expect_lobe_integrates_to_its_albedo;

// Nodes of the albedo block (the view's cosine along a row, the roughness down the block), as printed in Blender's
// table_sheen_ltc: a misread axis or block picks another number.
TEST(CyclesSheen, TheAlbedoAtTheTablesNodesIsTheTablesValue) {
  EXPECT_NEAR(cycles_sheen_albedo(1.0, 1.0), 0.34187, 1e-6);
  EXPECT_NEAR(cycles_sheen_albedo(0.0, 1.0), 0.74973, 1e-6);
  EXPECT_NEAR(cycles_sheen_albedo(15.0 / 31.0, 20.0 / 31.0), 0.27914, 1e-6);
  EXPECT_NEAR(cycles_sheen_albedo(5.0 / 31.0, 10.0 / 31.0), 0.33234, 1e-6);
}

TEST(CyclesSheen, TheLobeIntegratesToItsAlbedoAtEveryView) {
  expect_lobe_integrates_to_its_albedo(cycles_sheen_cosine_weighted, cycles_sheen_albedo, 1e-9);
}

// The paper's analytic fit is a fit of this table: within 0.02 of its albedo everywhere from roughness 0.3 up.
TEST(CyclesSheen, ThePapersAnalyticFitFollowsTheTable) {
  double largest = 0.0;
  for (double roughness = 0.3; roughness <= 1.0 + 1e-9; roughness += 0.05) {
    for (double mu = 0.0; mu <= 1.0 + 1e-9; mu += 0.05) {
      const double difference = std::abs(cycles_sheen_albedo(mu, roughness) - zeltner_fuzz_albedo(mu, roughness));
      largest = std::max(largest, difference);
      EXPECT_LT(difference, 0.02) << roughness << " " << mu;
    }
  }
  EXPECT_GT(largest, 1e-3);  // but they are not the same numbers
}

}  // namespace
}  // namespace skinlayer
