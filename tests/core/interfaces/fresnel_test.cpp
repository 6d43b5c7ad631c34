#include "core/interfaces/fresnel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace skinlayer {
namespace {

// Independent form: Snell's law and the s/p amplitude coefficients (Born & Wolf 1.5.2), averaged in power.
double fresnel_from_snell(double cos_i, double eta) {
  const double sin_t2 = (1.0 - cos_i * cos_i) / (eta * eta);
  if (sin_t2 >= 1.0) return 1.0;
  const double cos_t = std::sqrt(1.0 - sin_t2);
  const double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

TEST(FresnelDielectric, NormalIncidenceIsSquaredIndexRatio) {
  for (double eta : {1.0, 1.2, 1.4, 1.5, 2.5, 1.0 / 1.4}) {
    EXPECT_NEAR(fresnel_dielectric(1.0, eta), std::pow((eta - 1.0) / (eta + 1.0), 2), 1e-15) << eta;
  }
}

TEST(FresnelDielectric, MatchesSnellAmplitudeForm) {
  for (double eta : {1.1, 1.4, 2.5, 1.0 / 1.4, 0.5}) {
    for (double c = 0.01; c <= 1.0; c += 0.01) {
      EXPECT_NEAR(fresnel_dielectric(c, eta), fresnel_from_snell(c, eta), 1e-12) << "eta " << eta << " cos " << c;
    }
  }
}

TEST(FresnelDielectric, TotalInternalReflectionPastTheCriticalAngle) {
  const double eta = 1.0 / 1.4;  // from inside skin
  const double critical_sin = eta;
  const double critical_cos = std::sqrt(1.0 - critical_sin * critical_sin);
  EXPECT_EQ(fresnel_dielectric(critical_cos - 1e-6, eta), 1.0);
  EXPECT_EQ(fresnel_dielectric(0.1, eta), 1.0);
  EXPECT_LT(fresnel_dielectric(critical_cos + 1e-3, eta), 1.0);
  EXPECT_GT(fresnel_dielectric(critical_cos + 1e-3, eta), 0.5);
}

TEST(FresnelDielectric, IndexMatchedBoundaryReflectsNothingAndGrazingReflectsAll) {
  EXPECT_NEAR(fresnel_dielectric(0.3, 1.0), 0.0, 1e-30);
  EXPECT_NEAR(fresnel_dielectric(1e-9, 1.4), 1.0, 1e-8);
}

}  // namespace
}  // namespace skinlayer
