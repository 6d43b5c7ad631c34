#include "core/series/quadrature.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace skinlayer
