#include "core/fourier.h"

#include <gtest/gtest.h>

#include <cmath>

namespace skinlayer {
namespace {

// 1/(a - b cos phi) = (1/sqrt(a^2 - b^2)) (1 + 2 sum_{m>=1} r^m cos(m phi)),  r = (a - sqrt(a^2 - b^2)) / b.
TEST(CosineProjector, RecoversClosedFormCoefficientsOfPoissonKernel) {
  const double a = 2.0, b = 1.0;
  const double root = std::sqrt(a * a - b * b);
  const double r = (a - root) / b;
  const CosineProjector projector(12, 129);
  Eigen::MatrixXd samples(projector.samples(), 1);
  for (int k = 0; k < projector.samples(); ++k) samples(k, 0) = 1.0 / (a - b * std::cos(projector.angle(k)));
  const Eigen::MatrixXd coefficients = projector.project(samples);
  EXPECT_NEAR(coefficients(0, 0), 1.0 / root, 1e-14);
  for (int m = 1; m < 12; ++m) EXPECT_NEAR(coefficients(m, 0), 2.0 * std::pow(r, m) / root, 1e-14) << m;
}

TEST(CosineProjector, PureCosinesAreOrthonormalInTheFullCosineConvention) {
  const CosineProjector projector(8, 33);
  for (int j = 0; j < 8; ++j) {
    Eigen::MatrixXd samples(projector.samples(), 1);
    for (int k = 0; k < projector.samples(); ++k) samples(k, 0) = std::cos(j * projector.angle(k));
    const Eigen::MatrixXd c = projector.project(samples);
    for (int m = 0; m < 8; ++m) EXPECT_NEAR(c(m, 0), m == j ? 1.0 : 0.0, 1e-13) << j << " " << m;
  }
}

}  // namespace
}  // namespace skinlayer
