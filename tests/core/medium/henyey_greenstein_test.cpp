#include "core/medium/henyey_greenstein.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/conventions.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

TEST(HenyeyGreenstein, IsNormalizedAndHasMeanCosineG) {
  for (double g : {-0.9, 0.0, 0.5, 0.8, 0.95}) {
    const QuadratureRule rule = gauss_legendre(4000);
    double total = 0.0, mean = 0.0;
    for (int i = 0; i < rule.size(); ++i) {
      const double p = henyey_greenstein(rule.nodes[i], g) * 2.0 * kPi * rule.weights[i];
      total += p;
      mean += p * rule.nodes[i];
    }
    EXPECT_NEAR(total, 1.0, 1e-6) << g;
    EXPECT_NEAR(mean, g, 1e-6) << g;
  }
}

// Addition theorem: the azimuthal mean of HG is (1/4pi) sum_l (2l + 1) g^l P_l(mu) P_l(mu').
double legendre(int l, double x) {
  double p0 = 1.0, p1 = x;
  if (l == 0) return p0;
  for (int k = 1; k < l; ++k) {
    const double p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
    p0 = p1;
    p1 = p2;
  }
  return p1;
}

TEST(HenyeyGreensteinFourier, ModeZeroMatchesLegendreSeries) {
  const double g = 0.5;
  const CosineProjector projector(4, 257);
  const std::vector<double> from = {0.3, -0.7, 0.95};
  const std::vector<double> to = {0.1, 0.6, -0.4};
  const FourierKernel p = henyey_greenstein_fourier(g, from, to, projector);
  for (std::size_t a = 0; a < from.size(); ++a) {
    for (std::size_t b = 0; b < to.size(); ++b) {
      double series = 0.0;
      for (int l = 0; l < 200; ++l) series += (2.0 * l + 1.0) * std::pow(g, l) * legendre(l, from[a]) * legendre(l, to[b]);
      EXPECT_NEAR(p[0](b, a), series / (4.0 * kPi), 1e-12);
    }
  }
}

TEST(HenyeyGreensteinMatrices, ModeZeroConservesEnergyOnTheQuadratureAndStaysSymmetric) {
  const QuadratureRule rule = double_gauss_half_range(12);
  const CosineProjector projector(6, 301);
  for (double g : {0.0, 0.8, 0.95}) {
    const PhaseMatrices phase = henyey_greenstein_matrices(g, rule.nodes, rule.weights, projector);
    for (int i = 0; i < rule.size(); ++i) {
      double total = 0.0;
      for (int j = 0; j < rule.size(); ++j) {
        total += 2.0 * kPi * (phase.same[0](i, j) + phase.opposite[0](i, j)) * rule.weights[j];
      }
      EXPECT_NEAR(total, 1.0, 1e-13) << g;
    }
    for (int m = 0; m < 6; ++m) {
      EXPECT_NEAR((phase.same[m] - phase.same[m].transpose()).norm(), 0.0, 1e-12);
      EXPECT_NEAR((phase.opposite[m] - phase.opposite[m].transpose()).norm(), 0.0, 1e-12);
    }
  }
}

}  // namespace
}  // namespace skinlayer
