// The tabulated height-correlated transmission masking (core/interfaces/transmission_masking_table.h) against the
// closed form B(1/g_i, 1/g_o) it tabulates (smith_masking.h), at points between the grid's nodes, and its exact
// ends: B(1, b) = g_o, B(a, 1) = g_i, 0 where either G1 is 0.
#include "core/interfaces/transmission_masking_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/interfaces/microfacet_model.h"
#include "core/interfaces/smith_masking.h"

namespace skinlayer {
namespace {

TEST(TransmissionMaskingTable, FollowsTheBetaFunctionBetweenItsNodes) {
  // 401 x 401 points, irrational steps so that almost none is a node; the near-grazing corner included.
  double worst = 0.0, worst_inner = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const double g_i = std::min(1.0, i * 0.0024971);
    const TransmissionMaskingRow row(g_i);
    for (int j = 0; j <= 400; ++j) {
      const double g_o = std::min(1.0, j * 0.0024989);
      const double error = std::abs(row(g_o) - smith_g2_transmission(g_i, g_o, MicrofacetModel::Multiple));
      worst = std::max(worst, error);
      if (g_i > 0.2 && g_o > 0.2) worst_inner = std::max(worst_inner, error);
    }
  }
  EXPECT_LT(worst, 2e-6);
  EXPECT_LT(worst_inner, 2e-7);
}

TEST(TransmissionMaskingTable, IsExactWhereOneDirectionIsNeverMasked) {
  const TransmissionMaskingRow unmasked(1.0);
  for (const double g : {0.0, 0.013, 0.37, 0.8, 1.0}) {
    EXPECT_NEAR(unmasked(g), g, 1e-14) << g;                        // B(1, 1/g) = g
    EXPECT_NEAR(TransmissionMaskingRow(g)(1.0), g, 1e-14) << g;  // B(1/g, 1) = g
  }
  EXPECT_EQ(TransmissionMaskingRow(0.0)(0.5), 0.0);
  EXPECT_EQ(TransmissionMaskingRow(0.5)(0.0), 0.0);
}

}  // namespace
}  // namespace skinlayer
