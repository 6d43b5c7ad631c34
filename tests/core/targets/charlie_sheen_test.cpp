// glTF's sheen lobe as three.js has it: the Charlie distribution is a distribution of normals
// (its projected area is 1), the lobe is reciprocal, and three.js's fitted albedo E is compared with the lobe's own.
#include "core/targets/charlie_sheen.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "core/conventions.h"
#include "tests/core/targets/hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::over_hemisphere;

// int D(h) cos(theta_h) d omega_h = 1 for any roughness: the normals' projected area is the surface's.
TEST(CharlieSheen, TheDistributionProjectsToUnitArea) {
  for (const double r : {0.3, 0.6, 1.0}) {
    const double area =
        over_hemisphere<double>([&](const Vec3& h) { return charlie_sheen_distribution(h.z(), r) * h.z(); }, 200, 0.0);
    // three.js's hold on sin^2 (>= 2^-7) adds a sliver near the normal, where D is near 0 for these roughnesses.
    EXPECT_NEAR(area, 1.0, 2e-3) << r;
  }
}

TEST(CharlieSheen, IsReciprocal) {
  const Vec3 a = direction_from_angles(0.3, 0.0), b = direction_from_angles(1.1, 2.0);
  EXPECT_NEAR(charlie_sheen_cosine_weighted(0.5, a, b) / a.z(), charlie_sheen_cosine_weighted(0.5, b, a) / b.z(),
              1e-12);
}

// three.js's E is a fit of the Charlie lobe with Estevez & Kulla's visibility; with the Ashikhmin visibility the lobe
// is brighter. The fit stays within its own size of the lobe's albedo, so the layering's scaling is of the right
// size; the figures print for docs/model.md.
TEST(CharlieSheen, ThreeJsAlbedoFitIsOfTheLobesSize) {
  for (const double r : {0.3, 0.6, 1.0}) {
    for (const double theta : {0.0, 0.8, 1.3}) {
      const Vec3 view = direction_from_angles(theta, 0.0);
      const double lobe = over_hemisphere<double>(
          [&](const Vec3& light) { return charlie_sheen_cosine_weighted(r, light, view); }, 160, 0.0);
      const double fit = threejs_sheen_albedo(view.z(), r);
      std::printf("  sheen roughness %.1f view %.1f rad: lobe albedo %.4f, three.js E %.4f\n", r, theta, lobe, fit);
      EXPECT_GT(lobe, 0.0);
      EXPECT_LT(std::abs(lobe - fit), std::max(lobe, fit)) << r << " " << theta;
    }
  }
}

}  // namespace
}  // namespace skinlayer
