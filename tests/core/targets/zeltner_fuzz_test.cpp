// OpenPBR's fuzz (docs/model.md §22.3): the LTC is a density over the light's hemisphere, so the lobe's albedo at
// each view is its fitted E, which stays a fraction.
#include "core/targets/zeltner_fuzz.h"

#include <gtest/gtest.h>

#include "tests/core/targets/hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::over_hemisphere;

TEST(ZeltnerFuzz, TheLobeIntegratesToItsAlbedoAtEveryView) {
  for (const double roughness : {0.1, 0.5, 1.0}) {
    for (const double theta : {0.0, 0.6, 1.2, 1.5}) {
      const Vec3 view = direction_from_angles(theta, 0.4);
      const double integral = over_hemisphere<double>(
          [&](const Vec3& light) { return zeltner_fuzz_cosine_weighted(roughness, light, view); }, 128, 0.0);
      const double albedo = zeltner_fuzz_albedo(view.z(), roughness);
      EXPECT_NEAR(integral, albedo, 2e-3 * albedo + 1e-12) << roughness << " " << theta;
      EXPECT_GE(albedo, 0.0);
      EXPECT_LT(albedo, 1.0);
    }
  }
}

}  // namespace
}  // namespace skinlayer
