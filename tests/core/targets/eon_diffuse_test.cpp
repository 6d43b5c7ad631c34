// The energy-preserving Oren-Nayar diffuse (docs/model.md §22.3): its closed-form albedos are its integrals, a white
// surface reflects all the light at every roughness, it is reciprocal, and at roughness 0 it is Lambert's.
#include "core/targets/eon_diffuse.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/core/targets/hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::over_hemisphere;

TEST(EonDiffuse, ClosedFormAlbedosAreTheIntegralsOfTheLobe) {
  for (const double sigma : {0.0, 0.3, 1.0}) {
    for (const double theta : {0.0, 0.7, 1.4}) {
      const Vec3 view = direction_from_angles(theta, 0.0);
      const Rgb albedo(0.9, 0.5, 0.1);
      const Rgb integral = over_hemisphere<Rgb>(
          [&](const Vec3& light) { return eon_diffuse_cosine_weighted(albedo, sigma, light, view); }, 96, Rgb::Zero());
      const Rgb closed = eon_diffuse_albedo(albedo, sigma, std::cos(theta));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(integral(c), closed(c), 2e-4) << sigma << " " << theta;
    }
    // E_avg is twice the cosine-weighted mean of E_FON.
    const double average =
        2.0 *
        over_hemisphere<double>(
            [&](const Vec3& w) { return w.z() * eon_single_scattering_albedo(w.z(), sigma) / (2.0 * kPi); }, 64, 0.0);
    EXPECT_NEAR(average, eon_average_single_scattering_albedo(sigma), 1e-9) << sigma;
  }
}

TEST(EonDiffuse, AWhiteSurfaceReflectsAllTheLight) {
  for (const double sigma : {0.0, 0.25, 0.5, 1.0}) {
    for (const double theta : {0.0, 0.5, 1.0, 1.5}) {
      EXPECT_NEAR(eon_diffuse_albedo(Rgb::Ones(), sigma, std::cos(theta))(0), 1.0, 1e-12);
      const double integral = over_hemisphere<double>(
          [&](const Vec3& light) {
            return eon_diffuse_cosine_weighted(Rgb::Ones(), sigma, light, direction_from_angles(theta, 0.0))(0);
          },
          96, 0.0);
      EXPECT_NEAR(integral, 1.0, 2e-4) << sigma << " " << theta;
    }
  }
}

TEST(EonDiffuse, IsReciprocalAndLambertianWhenSmooth) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> theta(0.0, 1.5), phi(0.0, 2.0 * kPi);
  for (int k = 0; k < 200; ++k) {
    const Vec3 a = direction_from_angles(theta(random), phi(random)),
               b = direction_from_angles(theta(random), phi(random));
    const double f_ab = eon_diffuse_cosine_weighted(Rgb::Constant(0.6), 0.7, a, b)(0) / a.z();
    const double f_ba = eon_diffuse_cosine_weighted(Rgb::Constant(0.6), 0.7, b, a)(0) / b.z();
    EXPECT_NEAR(f_ab, f_ba, 1e-14);
    EXPECT_NEAR(eon_diffuse_cosine_weighted(Rgb::Constant(0.6), 0.0, a, b)(0), 0.6 * a.z() / kPi, 1e-15);
  }
}

}  // namespace
}  // namespace skinlayer
