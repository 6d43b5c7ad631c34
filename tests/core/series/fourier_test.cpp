#include "core/series/fourier.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

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

// e^{a cos phi} = I_0(a) + 2 sum_{m >= 1} I_m(a) cos(m phi) (Abramowitz & Stegun 9.6.34): a sharper lobe as a grows,
// so the adaptive series must take more modes for it, and each coefficient is known in closed form.
TEST(AdaptiveCosineSeries, FindsTheBesselCoefficientsOfAVonMisesLobeWithModesToMatch) {
  const AdaptiveCosineSeries adaptive(1024, 1e-8);
  std::size_t previous = 0;
  for (double a : {1.0, 20.0, 200.0}) {
    const std::vector<double> c = adaptive([a](double phi) { return std::exp(a * (std::cos(phi) - 1.0)); });
    EXPECT_GT(c.size(), previous) << a;
    previous = c.size();
    for (std::size_t m = 0; m < std::min<std::size_t>(c.size(), 40); ++m) {
      const double exact = (m == 0 ? 1.0 : 2.0) * std::cyl_bessel_i(static_cast<double>(m), a) * std::exp(-a);
      EXPECT_NEAR(c[m], exact, 1e-9) << "a " << a << " m " << m;
    }
  }
}

}  // namespace
}  // namespace skinlayer
