// The lobe plot's sampled unscattered BTDF (app/render/unscattered_plane.h): reused and re-weighed as the
// previewer's slider steps need, always equal to sampling afresh.
#include "app/render/unscattered_plane.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/conventions.h"
#include "core/material.h"

namespace skinlayer {
namespace {

Material sharp_layer(double transparency) {
  Material m;
  m.sigma = 0.2;
  m.tau = optical_depth_from_transparency(transparency);
  return m;
}

TEST(UnscatteredPlane, ATransparencyStepReweighsTheSameSamples) {
  const double theta_i = 0.6;
  const UnscatteredPlane before = sample_unscattered_plane(UnscatteredLight(sharp_layer(0.2)), theta_i);
  const UnscatteredLight after_light(sharp_layer(0.5));
  const UnscatteredPlane reweighed = sample_unscattered_plane(after_light, theta_i, 128, &before);
  const UnscatteredPlane fresh = sample_unscattered_plane(after_light, theta_i);
  ASSERT_EQ(reweighed.btdf.size(), fresh.btdf.size());
  EXPECT_EQ(reweighed.terms, before.terms);  // shared, not sampled anew
  EXPECT_TRUE(reweighed.light == after_light);
  double peak = 0.0;
  for (std::size_t k = 0; k < fresh.btdf.size(); ++k) {
    EXPECT_EQ(reweighed.btdf[k], fresh.btdf[k]) << k;
    const double s = unscattered_plane_angle(fresh, k);
    const double exact = after_light.btdf(theta_i, std::abs(s), s >= 0.0 ? kPi : 0.0);
    EXPECT_NEAR(fresh.btdf[k], exact, 1e-6 * exact + 1e-12) << k;
    peak = std::max(peak, exact);
  }
  EXPECT_GT(peak, 1.0);  // the lobe is there: T 0.5 through two sigma-0.2 interfaces peaks at several 1/sr
  // Another angle or other interfaces are sampled anew.
  const UnscatteredPlane moved = sample_unscattered_plane(after_light, 0.3, 128, &before);
  EXPECT_NE(moved.terms, before.terms);
  Material rougher = sharp_layer(0.5);
  rougher.sigma = 0.3;
  EXPECT_NE(sample_unscattered_plane(UnscatteredLight(rougher), theta_i, 128, &before).terms, before.terms);
}

}  // namespace
}  // namespace skinlayer
