// The GGX dielectric reflection of OpenPBR's specular and coat (docs/model.md §22.3): its tabulated albedo is the
// integral of its lobe, a smooth interface reflects its Fresnel, the compensation gives back, for a white Fresnel,
// all that single scattering loses (within MaterialX's fit), and that fit is GGX's albedo with Schlick's Fresnel.
#include "core/targets/ggx_dielectric_reflection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/interfaces/fresnel.h"
#include "core/targets/ggx_lobe.h"
#include "tests/core/targets/hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::over_hemisphere;

TEST(GgxDielectricReflection, ItsAlbedoIsTheIntegralOfItsLobe) {
  for (const double alpha : {0.09, 0.3, 1.0}) {
    const GgxDielectricReflection lobe(1.5, alpha);
    for (const double theta : {0.0, 0.45, 0.9, 1.3}) {
      const Vec3 view = direction_from_angles(theta, 1.0);
      const double integral =
          over_hemisphere<double>([&](const Vec3& light) { return lobe.cosine_weighted(light, view); }, 192, 0.0);
      EXPECT_NEAR(integral, lobe.albedo(view.z()), 2e-3 * lobe.albedo(view.z())) << alpha << " " << theta;
    }
  }
}

// A mirror reflects its Fresnel times the compensation, which MaterialX's fit (white albedo 0.92-1.003 at alpha
// 1e-8) leaves within 1% of 1.
TEST(GgxDielectricReflection, ASmoothInterfaceReflectsItsFresnel) {
  const GgxDielectricReflection mirror(1.6, 0.0);
  EXPECT_TRUE(mirror.smooth());
  for (const double mu : {1.0, 0.5, 0.1}) {
    // MaterialX 1.39 weighs its fit's loss by the Fresnel at the view: next to nothing where the fit is near 1.
    const GgxAlbedoTerms fit = materialx_ggx_albedo_terms(mu, 0.0);
    const double white = fit.a + fit.b;
    EXPECT_NEAR(mirror.compensation(mu), 1.0 + fresnel_dielectric(mu, 1.6) * (1.0 - white) / white, 1e-12) << mu;
    if (mu >= 0.5) {
      EXPECT_NEAR(mirror.compensation(mu), 1.0, 0.01) << mu;
    }
    EXPECT_NEAR(mirror.albedo(mu), fresnel_dielectric(mu, 1.6) * mirror.compensation(mu), 1e-3 * mirror.albedo(mu));
  }
  EXPECT_EQ(mirror.cosine_weighted(direction_from_angles(0.3, 0.0), direction_from_angles(0.3, kPi)), 0.0);
  // A nearly smooth one comes close to it.
  const GgxDielectricReflection sharp(1.6, 0.01);
  for (const double mu : {1.0, 0.5})
    EXPECT_NEAR(sharp.albedo(mu), fresnel_dielectric(mu, 1.6), 0.01 * sharp.albedo(mu));
}

// With the Fresnel at 1 everywhere (an index so high that F_avg is within 1e-3 of 1), the compensated albedo is
// E_ss (1 + (1 - E_w) / E_w) = E_ss / E_w: all of it, as far as MaterialX's fit E_w is the integral E_ss (within 2%
// at these roughnesses and views).
TEST(GgxDielectricReflection, CompensationGivesBackWhatSingleScatteringLoses) {
  const double eta = 1e4;
  const double f0 = fresnel_dielectric(1.0, eta), average = f0 + (1.0 - f0) / 21.0;
  ASSERT_GT(average, 0.999);
  for (const double alpha : {0.2, 0.6, 1.0}) {
    const GgxDielectricReflection lobe(eta, alpha);
    for (const double mu : {1.0, 0.6, 0.2}) EXPECT_NEAR(lobe.albedo(mu), 1.0, 0.02) << alpha << " " << mu;
  }
}

// MaterialX's rational fit against the albedo integrated here with Schlick's Fresnel split into its F0 and F90
// parts, F0 (1 - (1 - c)^5) + F90 (1 - c)^5: within 0.03 of each (the fit's own accuracy; a wrong coefficient moves
// it by far more).
TEST(GgxDielectricReflection, MaterialXsFitIsTheSchlickAlbedo) {
  for (const double alpha : {0.09, 0.3, 0.6, 1.0}) {
    for (const double mu : {1.0, 0.6, 0.4, 0.2}) {
      const Vec3 view(std::sqrt(1.0 - mu * mu), 0.0, mu);
      const Rgb integral = microfacet_lobe_albedo(
          [&](const Vec3& light) {
            const Vec3 h = (light + view).normalized();
            const double single =
                ggx_distribution(h.z(), alpha) * ggx_height_correlated_masking(light.z(), mu, alpha) / (4.0 * mu);
            const double tail = std::pow(1.0 - std::max(0.0, light.dot(h)), 5.0);
            return Rgb(single * (1.0 - tail), single * tail, 0.0);
          },
          view, alpha, 24);
      const GgxAlbedoTerms fit = materialx_ggx_albedo_terms(mu, alpha);
      EXPECT_NEAR(fit.a, integral(0), 0.03) << alpha << " " << mu;
      EXPECT_NEAR(fit.b, integral(1), 0.03) << alpha << " " << mu;
    }
  }
}

// What a layer of the lobe passes on is the fit with Schlick's Fresnel, compensated; it differs from the lobe's own
// albedo (exact Fresnel) by a few thousandths at an index of 1.5.
TEST(GgxDielectricReflection, TheLayersAlbedoIsTheCompensatedSchlickFit) {
  const GgxDielectricReflection lobe(1.5, 0.3);
  for (const double mu : {1.0, 0.5, 0.2}) {
    const GgxAlbedoTerms fit = materialx_ggx_albedo_terms(mu, 0.3);
    EXPECT_NEAR(lobe.layer_albedo(mu), lobe.compensation(mu) * (0.04 * fit.a + fit.b), 1e-12);
    EXPECT_NEAR(lobe.layer_albedo(mu), lobe.albedo(mu), 0.01) << mu;
  }
}

}  // namespace
}  // namespace skinlayer
