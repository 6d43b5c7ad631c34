// Single scattering under a rough top (core/spatial/rough_top_single_scattering.h): the closed-form first order of
// the full lateral solve, its limit for many azimuthal modes, and the real-space forms that the profile adds back.
#include "core/spatial/rough_top_single_scattering.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/interfaces/microfacet.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

RoughDielectric skin_like_top(double sigma) {
  RoughDielectric top;
  top.eta = 1.4;
  top.sigma = sigma;
  top.microfacet = MicrofacetModel::Multiple;
  return top;
}

// The full solve is R(Omega) = a Omega + b Omega^2 + ...; 2 R(e)/e - R(2e)/(2e) = a + O(e^2). At e = 1e-3 that leaves
// ~1e-6 of a, and the full solve's rounding (~1e-12 absolute) 1e-6 more.
TEST(RoughTopSingleScattering, IsTheFirstOrderInTheAlbedoOfTheFullSolve) {
  for (const double tau : {1.0, kInf}) {
    for (const double g : {0.0, 0.8}) {
      const LateralFrequencyResolution resolution{12, 16};
      const LateralTopInterface top = lateral_top_interface(skin_like_top(0.5), 12, 16);
      for (const double k : {0.0, 2.0, 10.0, 50.0}) {
        constexpr double e = 1e-3;
        const double once = rough_top_lateral_response(tau, e, g, top, k, resolution).reflectance / e;
        const double twice = rough_top_lateral_response(tau, 2.0 * e, g, top, k, resolution).reflectance / (2.0 * e);
        const double extrapolated = 2.0 * once - twice;
        const LateralSlab slab[] = {{tau, 1.0, g}};
        const double first_order = rough_top_low_orders(slab, top, k, resolution).reflected_once;
        std::printf("  tau %4.1f g %.1f k %4.0f  first order %.9f  extrapolated %.9f (%+.1e)\n", tau, g, k, first_order,
                    extrapolated, first_order / extrapolated - 1.0);
        EXPECT_NEAR(first_order, extrapolated, 1e-5 * first_order) << tau << " " << g << " " << k;
      }
    }
  }
}

// The same for a two-slab stack whose lower slab is denser (relative extinction 3), at every frequency: each slab's
// streaming sees k in its own mean free paths.
TEST(RoughTopSingleScattering, InAStackIsTheFirstOrderInTheAlbedosOfTheFullSolve) {
  const LateralFrequencyResolution resolution{12, 16};
  const LateralTopInterface top = lateral_top_interface(skin_like_top(0.4), 12, 16);
  for (const double k : {0.0, 1.0, 10.0}) {
    constexpr double e = 1e-3;
    const LateralSlab weak[] = {{0.6, 0.5 * e, 0.7, 1.0}, {kInf, e, 0.85, 3.0}};
    const LateralSlab weaker[] = {{0.6, e, 0.7, 1.0}, {kInf, 2.0 * e, 0.85, 3.0}};
    const LateralSlab unit[] = {{0.6, 0.5, 0.7, 1.0}, {kInf, 1.0, 0.85, 3.0}};
    const double once = lateral_stack_response(weak, &top, k, resolution).reflectance / e;
    const double twice = lateral_stack_response(weaker, &top, k, resolution).reflectance / (2.0 * e);
    const double first_order = rough_top_low_orders(unit, top, k, resolution).reflected_once;
    EXPECT_NEAR(first_order, 2.0 * once - twice, 1e-5 * first_order) << k;
  }
  // At k = 0, the closed form of the stack.
  const LateralSlab unit[] = {{0.6, 0.5, 0.7, 1.0}, {kInf, 1.0, 0.85, 3.0}};
  EXPECT_NEAR(rough_top_single_scattered_power(unit, top, 12, 0.0, kInf),
              rough_top_low_orders(unit, top, 0.0, resolution).reflected_once, 1e-9);
}

// With the azimuth integrated exactly the closed forms are the ordinates' single scattering with infinitely many
// modes: equal to the first order at k = 0 whatever the modes, and its limit as they grow at every k.
TEST(RoughTopSingleScattering, ClosedFormsAreTheManyModeLimitOfTheOrdinates) {
  const RoughDielectric interface = skin_like_top(0.8);
  const LateralTopInterface top = lateral_top_interface(interface, 12, 40);
  const LateralSlab half_space[] = {{kInf, 0.9, 0.8}};
  const double total = rough_top_single_scattered_transform(0.9, 0.8, top, 12, 0.0);
  EXPECT_NEAR(rough_top_single_scattered_power(half_space, top, 12, 0.0, kInf), total, 1e-12);
  EXPECT_NEAR(rough_top_low_orders(half_space, top, 0.0, {12, 4}).reflected_once, total, 1e-9 * total);
  for (const double k : {1.0, 10.0, 50.0}) {
    const double closed = rough_top_single_scattered_transform(0.9, 0.8, top, 12, k);
    const double many = rough_top_low_orders(half_space, top, k, {12, 40}).reflected_once;
    std::printf("  k %4.0f  closed form %.9f  40 modes %.9f (%+.1e)\n", k, closed, many, many / closed - 1.0);
    EXPECT_NEAR(many, closed, 2e-4 * closed) << k;
  }
}

// The density integrated over an annulus (2 pi r dr, Gauss-Legendre panels graded towards the beam) is its power.
TEST(RoughTopSingleScattering, DensityIntegratesToTheAnnulusPower) {
  const LateralTopInterface top = lateral_top_interface(skin_like_top(0.5), 12, 4);
  const LateralSlab half_space[] = {{kInf, 0.9, 0.6}};
  for (const auto& [r0, r1] : {std::pair{0.01, 0.1}, std::pair{0.1, 0.5}, std::pair{0.5, 2.0}, std::pair{2.0, 6.0}}) {
    double integral = 0.0;
    const int panels = 16;
    for (int p = 0; p < panels; ++p) {  // geometric panels
      const double a = r0 * std::pow(r1 / r0, double(p) / panels), b = r0 * std::pow(r1 / r0, double(p + 1) / panels);
      integral += integrate_mapped(gauss_legendre(16, 0.0, 1.0), a, b, [&](double r) {
        return 2.0 * 3.14159265358979323846 * r * rough_top_single_scattered_density(half_space, top, 12, r);
      });
    }
    const double power = rough_top_single_scattered_power(half_space, top, 12, r0, r1);
    EXPECT_NEAR(integral, power, 1e-6 * power) << r0 << " " << r1;
  }
  // Across a slab's face the density is continuous in r but not smooth: a stack's annuli need the panels too.
  const LateralSlab stack[] = {{0.7, 0.8, 0.8, 1.0}, {kInf, 0.95, 0.8, 2.5}};
  for (const auto& [r0, r1] : {std::pair{0.05, 0.3}, std::pair{0.3, 1.5}}) {
    double integral = 0.0;
    const int panels = 64;
    for (int p = 0; p < panels; ++p) {
      const double a = r0 + (r1 - r0) * p / panels, b = r0 + (r1 - r0) * (p + 1) / panels;
      integral += integrate_mapped(gauss_legendre(8, 0.0, 1.0), a, b, [&](double r) {
        return 2.0 * 3.14159265358979323846 * r * rough_top_single_scattered_density(stack, top, 12, r);
      });
    }
    const double power = rough_top_single_scattered_power(stack, top, 12, r0, r1);
    EXPECT_NEAR(integral, power, 1e-4 * power) << r0 << " " << r1;
  }
  EXPECT_THROW(rough_top_single_scattered_density(half_space, top, 12, 0.0), std::invalid_argument);
  EXPECT_THROW(rough_top_single_scattered_power(half_space, top, 12, 1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(rough_top_single_scattered_power(half_space, top, 10, 0.0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace skinlayer
