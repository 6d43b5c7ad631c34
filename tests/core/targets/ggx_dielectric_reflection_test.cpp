// The GGX dielectric reflection of OpenPBR's specular and coat (docs/model.md §22.3): its tabulated albedo is the
// integral of its lobe, a smooth interface reflects its Fresnel, and the compensation gives back, for a white
// Fresnel, all that single scattering loses.
#include "core/targets/ggx_dielectric_reflection.h"

#include <gtest/gtest.h>

#include "core/interfaces/fresnel.h"
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

TEST(GgxDielectricReflection, ASmoothInterfaceReflectsItsFresnel) {
  const GgxDielectricReflection mirror(1.6, 0.0);
  EXPECT_TRUE(mirror.smooth());
  for (const double mu : {1.0, 0.5, 0.1}) EXPECT_NEAR(mirror.albedo(mu), fresnel_dielectric(mu, 1.6), 1e-3);
  EXPECT_EQ(mirror.cosine_weighted(direction_from_angles(0.3, 0.0), direction_from_angles(0.3, kPi)), 0.0);
  // A nearly smooth one comes close to it.
  const GgxDielectricReflection sharp(1.6, 0.01);
  for (const double mu : {1.0, 0.5})
    EXPECT_NEAR(sharp.albedo(mu), fresnel_dielectric(mu, 1.6), 0.01 * sharp.albedo(mu));
}

// With the Fresnel at 1 everywhere (an index so high that F_avg is within 1e-3 of 1), the compensated albedo is
// F_avg (1 - E_ss) + E_ss: all of it, up to 1 - F_avg, however rough.
TEST(GgxDielectricReflection, CompensationGivesBackWhatSingleScatteringLoses) {
  const double eta = 1e4;
  const double f0 = fresnel_dielectric(1.0, eta), average = f0 + (1.0 - f0) / 21.0;
  ASSERT_GT(average, 0.999);
  for (const double alpha : {0.2, 0.6, 1.0}) {
    const GgxDielectricReflection lobe(eta, alpha);
    for (const double mu : {1.0, 0.6, 0.2}) EXPECT_NEAR(lobe.albedo(mu), 1.0, 2e-3) << alpha << " " << mu;
  }
}

}  // namespace
}  // namespace skinlayer
