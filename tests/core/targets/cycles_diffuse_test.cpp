// Cycles' Principled diffuse (docs/model.md §22.1.1): its closed-form albedo is the integral of its lobe, a white
// surface reflects all the light at every roughness, it is reciprocal, it is Lambert's below 1e-5, and its multiple
// scattering is the colour times EON's.
#include "core/targets/cycles_diffuse.h"

#include <gtest/gtest.h>

#include <random>

#include "core/conventions.h"
#include "core/targets/eon_diffuse.h"
#include "tests/core/targets/hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::over_hemisphere;

TEST(CyclesDiffuse, ClosedFormAlbedoIsTheIntegralAndWhiteIsWhole) {
  const Rgb color(0.9, 0.5, 0.1);
  for (const double sigma : {0.0, 0.3, 1.0}) {
    for (const double theta : {0.0, 0.7, 1.4}) {
      const Vec3 view = direction_from_angles(theta, 0.0);
      const Rgb integral = over_hemisphere<Rgb>(
          [&](const Vec3& light) { return cycles_diffuse_cosine_weighted(color, sigma, light, view); }, 96,
          Rgb::Zero());
      const Rgb closed = cycles_diffuse_albedo(color, sigma, view.z());
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(integral(c), closed(c), 2e-4) << sigma << " " << theta;
      EXPECT_NEAR(cycles_diffuse_albedo(Rgb::Ones(), sigma, view.z())(0), 1.0, 1e-12) << sigma << " " << theta;
    }
  }
}

TEST(CyclesDiffuse, IsReciprocalAndLambertAtRoughnessZero) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> theta(0.0, 1.5), phi(0.0, 2.0 * kPi);
  const Rgb color(0.7, 0.3, 0.05);
  for (int n = 0; n < 100; ++n) {
    const Vec3 a = direction_from_angles(theta(random), phi(random)),
               b = direction_from_angles(theta(random), phi(random));
    const Rgb ab = cycles_diffuse_cosine_weighted(color, 0.6, a, b) / a.z();
    const Rgb ba = cycles_diffuse_cosine_weighted(color, 0.6, b, a) / b.z();
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ab(c), ba(c), 1e-12);
    const Rgb lambert = cycles_diffuse_cosine_weighted(color, 0.0, a, b);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(lambert(c), color(c) * a.z() / kPi, 1e-15);
  }
}

// At roughness sigma the single scattering is EON's (white, times the colour); the multiple scattering is the colour
// times EON's for that colour: f_cycles(rho) - rho f_FON = rho (f_eon(rho) - rho f_FON).
TEST(CyclesDiffuse, MultipleScatteringIsTheColourTimesEons) {
  const Vec3 light = direction_from_angles(0.5, 0.0), view = direction_from_angles(1.1, 2.5);
  const double sigma = 0.8;
  const Rgb rho(0.8, 0.4, 0.1);
  const double white_eon = eon_diffuse_cosine_weighted(Rgb::Ones(), sigma, light, view)(0);
  const double white_multiple = light.z() * (1.0 - eon_single_scattering_albedo(light.z(), sigma)) *
                                (1.0 - eon_single_scattering_albedo(view.z(), sigma)) /
                                (kPi * (1.0 - eon_average_single_scattering_albedo(sigma)));
  const double single = white_eon - white_multiple;
  const Rgb cycles = cycles_diffuse_cosine_weighted(rho, sigma, light, view);
  const Rgb eon = eon_diffuse_cosine_weighted(rho, sigma, light, view);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(cycles(c) - rho(c) * single, rho(c) * (eon(c) - rho(c) * single), 1e-14) << c;
    EXPECT_LT(cycles(c), eon(c));  // darker than EON for a colour below white
  }
}

}  // namespace
}  // namespace skinlayer
