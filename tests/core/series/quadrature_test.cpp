#include "core/series/quadrature.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace skinlayer {
namespace {

// int_{-1}^{1} x^k dx = 2/(k+1) for even k, 0 for odd k.
double monomial_integral(int k) { return k % 2 == 1 ? 0.0 : 2.0 / (k + 1); }

TEST(GaussLegendre, IntegratesPolynomialsUpToDegree2nMinus1Exactly) {
  for (int n : {1, 2, 3, 8, 16, 33, 64}) {
    const QuadratureRule rule = gauss_legendre(n);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], k);
      EXPECT_NEAR(sum, monomial_integral(k), 1e-13) << "n = " << n << ", degree " << k;
    }
  }
}

TEST(GaussLegendre, IsNotExactAtDegree2n) {
  const int n = 4;
  const QuadratureRule rule = gauss_legendre(n);
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], 2 * n);
  EXPECT_GT(std::abs(sum - monomial_integral(2 * n)), 1e-4);
}

TEST(DoubleGauss, HalfRangeMomentsAreExactAndNoNodeAtZero) {
  for (int n : {4, 16, 24, 64}) {
    const QuadratureRule rule = double_gauss_half_range(n);
    EXPECT_NEAR(std::accumulate(rule.weights.begin(), rule.weights.end(), 0.0), 1.0, 1e-14);
    EXPECT_GT(rule.nodes.front(), 0.0);
    EXPECT_LT(rule.nodes.back(), 1.0);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], k);
      EXPECT_NEAR(sum, 1.0 / (k + 1), 1e-13) << "n = " << n << ", moment " << k;
    }
    for (int i = 1; i < n; ++i) EXPECT_LT(rule.nodes[i - 1], rule.nodes[i]);
  }
}

// Graded panels tile [from, to) without gaps, break where a lobe starting at `from` needs them, and stay within the
// widest width; the composite rule on them integrates what each panel's rule does exactly.
TEST(GaussLegendrePanels, GradedPanelsTileTheRangeAndIntegratePiecewisePolynomials) {
  const auto panels = graded_panels(0.0, 1.5, 0.1, 0.25);
  ASSERT_FALSE(panels.empty());
  EXPECT_EQ(panels.front().first, 0.0);
  EXPECT_EQ(panels.back().second, 1.5);
  for (std::size_t i = 0; i < panels.size(); ++i) {
    EXPECT_LT(panels[i].first, panels[i].second);
    EXPECT_LE(panels[i].second - panels[i].first, 0.25 + 1e-15);
    if (i > 0) {
      EXPECT_EQ(panels[i].first, panels[i - 1].second);
    }
  }
  for (const double edge : {0.05, 0.1, 0.2, 0.4}) {
    EXPECT_TRUE(std::any_of(panels.begin(), panels.end(), [&](const auto& p) { return p.first == edge; })) << edge;
  }
  EXPECT_EQ(graded_panels(0.0, 1.0, 0.0, 2.0).size(), 1u);  // no lobe, one panel
  // |x - 0.2|^3 has a kink at a panel edge: 4 points per panel integrate it exactly.
  const QuadratureRule rule = gauss_legendre_panels(panels, 4);
  ASSERT_EQ(rule.size(), 4 * static_cast<int>(panels.size()));
  double sum = 0.0;
  for (int i = 0; i < rule.size(); ++i) sum += rule.weights[i] * std::pow(std::abs(rule.nodes[i] - 0.2), 3);
  EXPECT_NEAR(sum, (std::pow(0.2, 4) + std::pow(1.3, 4)) / 4.0, 1e-13);
}

}  // namespace
}  // namespace skinlayer
