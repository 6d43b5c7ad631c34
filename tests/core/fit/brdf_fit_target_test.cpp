// The pairs a shader fit samples and the errors it reports (docs/model.md §22.2).
#include "core/fit/brdf_fit_target.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/conventions.h"

namespace skinlayer {
namespace {

// The pairs: for each light, the view's hemisphere and a cap about the mirror direction, each weighted by its solid
// angle, so that for light from the normal the weights add to 2 pi plus the cap's 2 pi (1 - cos 30 degrees). At 80
// degrees the cap's part below the horizon is left out: of a 30-degree cap about a direction 10 degrees up, 70.41%
// is above it (a midpoint sum on 4000 x 720 cells); the cap's nodes, which do not stop at the horizon, come within 1%.
TEST(FitPairs, CoverTheHemisphereAndACapAboutTheMirror) {
  const std::vector<DirectionPair> pairs = fit_pairs();
  double normal = 0.0, grazing = 0.0;
  for (const DirectionPair& pair : pairs) {
    ASSERT_GT(pair.omega_o.z(), 0.0);
    EXPECT_NEAR(pair.omega_o.norm(), 1.0, 1e-12);
    if (pair.omega_i.z() == 1.0) normal += pair.weight;
    if (std::abs(pair.omega_i.z() - std::cos(degrees_to_radians(80.0))) < 1e-12) grazing += pair.weight;
  }
  const double cap = 2.0 * kPi * (1.0 - std::cos(degrees_to_radians(kMirrorCapDegrees)));
  EXPECT_NEAR(normal, 2.0 * kPi + cap, 1e-9);
  EXPECT_NEAR(grazing, 2.0 * kPi + 0.7041 * cap, 0.01 * cap);
}

// The errors are zero for the target itself, and relative: a BRDF 10% above the target everywhere is 10% off at
// worst in the lobe (at its peak) and in every albedo.
TEST(FitErrors, AreRelativeToTheTarget) {
  BrdfFitTarget target;
  target.pairs = fit_pairs(4);
  const auto lambert = [](const Vec3& omega_i, const Vec3&) { return Rgb(Rgb(0.5, 0.3, 0.1) * omega_i.z() / kPi); };
  for (const DirectionPair& pair : target.pairs) target.brdf_cosine.push_back(lambert(pair.omega_i, pair.omega_o));
  target.albedo_angles = {0.0, 1.0};
  target.albedo = {Rgb(0.5, 0.3, 0.1), Rgb(0.5, 0.3, 0.1)};
  const FitErrors exact = fit_errors(target, lambert, [](double) { return Rgb(0.5, 0.3, 0.1); });
  EXPECT_EQ(exact.lobe_worst.maxCoeff(), 0.0);
  EXPECT_EQ(exact.albedo_worst.maxCoeff(), 0.0);
  const FitErrors high = fit_errors(
      target, [&](const Vec3& i, const Vec3& o) { return Rgb(1.1 * lambert(i, o)); },
      [](double) { return Rgb(0.55, 0.33, 0.11); });
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(high.lobe_worst(c), 0.1, 1e-12);
    EXPECT_GT(high.lobe_rms(c), 0.0);
    EXPECT_LT(high.lobe_rms(c), 0.1);
    EXPECT_NEAR(high.albedo_worst(c), 0.1, 1e-12);
    EXPECT_NEAR(high.albedo_rms(c), 0.1, 1e-12);
  }
  target.albedo_angles = {0.5, 1.0};
  EXPECT_THROW(check_fit_target(target), std::invalid_argument);
}

}  // namespace
}  // namespace skinlayer
