// The response at one lateral spatial frequency (core/spatial/lateral_frequency_response.h), against the BSDF
// solver at k = 0 and against the closed form of single scattering at every k.
//
// Single scattering under an open top, in k-space: the Hankel transform of R1(r)
// (tests/core/reference/monte_carlo_positions_test.cpp) is, with int_0^inf e^{-a z} J0(b z) dz = 1/sqrt(a^2 + b^2),
//   R1(k) = Omega 2 pi int_0^1 p(-mu) mu / sqrt((1 + mu)^2 + k^2 (1 - mu^2)) dmu,
// and T1(k) for a slab of depth tau_b follows in the same way from the light scattered once towards the bottom. The
// solver's answer is linear in Omega plus O(Omega^2), so at Omega 1e-4 it must equal these to ~1e-4 relative, plus its
// own discretization: 16 nodes err by 3.7e-4 on g 0.8's backscatter, 24 modes by 5.5e-4 at k 10, both shrinking with
// the resolution.
#include "core/spatial/lateral_frequency_response.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/medium/henyey_greenstein.h"
#include "core/series/quadrature.h"
#include "core/solver.h"
#include "core/spatial/lateral_top_interface.h"
#include "tests/core/index_matched_slab.h"

namespace skinlayer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// R1(k) / Omega for the semi-infinite open layer, by Gauss-Legendre panels in mu.
double single_scattering_reflectance(double g, double k) {
  double total = 0.0;
  for (const auto& [a, b] : {std::pair{0.0, 0.1}, std::pair{0.1, 0.5}, std::pair{0.5, 1.0}}) {
    const QuadratureRule rule = gauss_legendre(64, a, b);
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      const double mu = rule.nodes[i];
      total += rule.weights[i] * henyey_greenstein(-mu, g) * mu /
               std::sqrt((1.0 + mu) * (1.0 + mu) + k * k * (1.0 - mu * mu));
    }
  }
  return 2.0 * kPi * total;
}

// At k = 0 every mode decouples and mode 0 is the BSDF's azimuthal average: R(0) is the subsurface reflectance at
// normal incidence and T(0) the scattered transmittance, to the solvers' common discretization.
TEST(LateralFrequencyResponse, AtZeroFrequencyItIsTheDirectionalAlbedo) {
  for (const double tau : {0.5, 2.0, kInf}) {
    for (const double g : {0.0, 0.8}) {
      Material m = test::index_matched_slab(tau, 0.95, g);
      m.ordinates = 16;
      const double theta[] = {0.0};
      const DirectionalAlbedo albedo = directional_albedo(m, theta).front();
      const LateralFrequencyResponse at_zero = open_layer_lateral_response(tau, 0.95, g, 0.0, {16, 4});
      const double direct = std::isinf(tau) ? 0.0 : std::exp(-tau);
      std::printf("  tau %4.1f g %.1f  R(0) %.9f  solver %.9f   T(0) %.9f  solver %.9f\n", tau, g, at_zero.reflectance,
                  albedo.reflectance_subsurface, at_zero.transmittance, albedo.transmittance - direct);
      EXPECT_NEAR(at_zero.reflectance, albedo.reflectance_subsurface, 1e-6) << "tau " << tau << " g " << g;
      EXPECT_NEAR(at_zero.transmittance, albedo.transmittance - direct, 1e-6) << "tau " << tau << " g " << g;
    }
  }
}

// Under a rough top the solve takes the BSDF's own top operators, so at k = 0 it is the BSDF's directional albedo
// again: the subsurface reflectance less the interface's multiply scattered reflection (which leaves where the beam
// enters), and all the light through a matched bottom.
TEST(LateralFrequencyResponse, UnderARoughTopAtZeroFrequencyItIsTheDirectionalAlbedo) {
  for (const double sigma : {0.5, 1.0}) {
    for (const double tau : {2.0, kInf}) {
      Material m = test::index_matched_slab(tau, 0.9, 0.8);
      m.eta = 1.4;
      m.sigma = sigma;
      m.ordinates = 12;
      const double theta[] = {0.0};
      const DirectionalAlbedo albedo = directional_albedo(m, theta).front();
      const LateralTopInterface top = lateral_top_interface(top_interface(m), 12, 4);
      const LateralFrequencyResponse at_zero = rough_top_lateral_response(tau, 0.9, 0.8, top, 0.0, {12, 4});
      std::printf("  sigma %.1f tau %4.1f  R(0) + surface %.9f  solver %.9f   T(0) %.9f  solver %.9f\n", sigma, tau,
                  at_zero.reflectance + top.surface_multiple_reflectance, albedo.reflectance_subsurface,
                  at_zero.transmittance, albedo.transmittance);
      EXPECT_GT(top.surface_multiple_reflectance, 0.0);
      EXPECT_NEAR(at_zero.reflectance + top.surface_multiple_reflectance, albedo.reflectance_subsurface, 1e-6);
      EXPECT_NEAR(at_zero.transmittance, albedo.transmittance, 1e-6);
    }
  }
}

// At every k the first order in Omega is single scattering, whose transform is a closed form: this checks the
// coupling of the azimuthal modes by the k.s term, mode by mode, where R(k) falls by two decades.
TEST(LateralFrequencyResponse, WeakScatteringIsTheClosedFormOfSingleScatteringAtEveryFrequency) {
  constexpr double kAlbedo = 1e-4;
  for (const double g : {0.0, 0.8}) {
    for (const double k : {0.0, 0.3, 1.0, 3.0, 10.0}) {
      const LateralFrequencyResponse r = open_layer_lateral_response(kInf, kAlbedo, g, k, {16, 24});
      const double expected = single_scattering_reflectance(g, k);
      std::printf("  g %.1f k %5.1f  R(k)/Omega %.7f  closed form %.7f  (%+.2e)\n", g, k, r.reflectance / kAlbedo,
                  expected, r.reflectance / kAlbedo / expected - 1.0);
      EXPECT_NEAR(r.reflectance / kAlbedo, expected, 1e-3 * expected) << "g " << g << " k " << k;
    }
  }
  // Converged with the resolution: 24 nodes and 40 modes at k 10.
  const double fine = open_layer_lateral_response(kInf, kAlbedo, 0.8, 10.0, {24, 40}).reflectance / kAlbedo;
  EXPECT_NEAR(fine, single_scattering_reflectance(0.8, 10.0), 1e-4 * fine);
}

// The discretization's single scattering, solved without the scattering operator (one small eigen-solve per node),
// is the full solve's first order in the albedo, and its closed form to the same 1e-3.
TEST(LateralFrequencyResponse, SingleScatteringIsTheFirstOrderOfTheFullSolve) {
  for (const double tau : {1.5, kInf}) {
    for (const double k : {0.0, 0.7, 4.0}) {
      const LateralFrequencyResponse once = open_layer_single_scattering_response(tau, 0.9, 0.6, k, {12, 16});
      const LateralFrequencyResponse weak = open_layer_lateral_response(tau, 1e-7, 0.6, k, {12, 16});
      EXPECT_NEAR(once.reflectance / 0.9, weak.reflectance / 1e-7, 1e-6 * once.reflectance / 0.9) << tau << " " << k;
      EXPECT_NEAR(once.transmittance / 0.9, weak.transmittance / 1e-7, 1e-6 * once.transmittance / 0.9 + 1e-15)
          << tau << " " << k;
    }
  }
  const double expected = single_scattering_reflectance(0.6, 4.0);
  EXPECT_NEAR(open_layer_single_scattering_response(kInf, 1.0, 0.6, 4.0, {16, 24}).reflectance, expected,
              1e-3 * expected);
}

// A slab cut in two is the same slab, at every frequency and under either top: the faces between slabs join every
// mode of every node.
TEST(LateralFrequencyResponse, CuttingASlabInTwoChangesNothing) {
  Material m;
  m.eta = 1.4;
  m.sigma = 0.5;
  const LateralTopInterface rough = lateral_top_interface(top_interface(m), 12, 16);
  for (const LateralTopInterface* top : {static_cast<const LateralTopInterface*>(nullptr), &rough}) {
    for (const double k : {0.0, 0.7, 5.0}) {
      const LateralSlab whole[] = {{3.0, 0.9, 0.7}};
      const LateralSlab cut[] = {{1.2, 0.9, 0.7}, {1.8, 0.9, 0.7}};
      const LateralFrequencyResponse one = lateral_stack_response(whole, top, k, {12, 16});
      const LateralFrequencyResponse two = lateral_stack_response(cut, top, k, {12, 16});
      EXPECT_NEAR(two.reflectance, one.reflectance, 1e-9 * one.reflectance) << k;
      EXPECT_NEAR(two.transmittance, one.transmittance, 1e-9 * one.transmittance) << k;
    }
  }
}

// At k = 0 a two-slab stack under a rough top is the stack solver's directional albedo at normal incidence.
TEST(LateralFrequencyResponse, AStackAtZeroFrequencyIsTheStackSolversAlbedo) {
  for (const double tau_below : {1.5, kInf}) {
    Material m = test::index_matched_slab(0.8, 0.7, 0.8);
    m.eta = 1.4;
    m.sigma = 0.6;
    m.ordinates = 12;
    m.below = {StackedLayer{tau_below, 0.95, 0.6, std::nullopt}};
    const double theta[] = {0.0};
    const DirectionalAlbedo albedo = directional_albedo(m, theta).front();
    const LateralTopInterface top = lateral_top_interface(top_interface(m), 12, 4);
    const LateralSlab slabs[] = {{0.8, 0.7, 0.8}, {tau_below, 0.95, 0.6}};
    const LateralFrequencyResponse at_zero = lateral_stack_response(slabs, &top, 0.0, {12, 4});
    EXPECT_NEAR(at_zero.reflectance + top.surface_multiple_reflectance, albedo.reflectance_subsurface, 1e-6);
    EXPECT_NEAR(at_zero.transmittance, albedo.transmittance, 1e-6);
  }
}

// Lengths are the first slab's mean free paths: scaling every slab's extinction and the frequency together changes
// nothing, while a denser lower slab (the same optical depth, half the thickness) spreads the light less.
TEST(LateralFrequencyResponse, EachSlabSeesTheFrequencyInItsOwnMeanFreePaths) {
  const LateralSlab slabs[] = {{0.5, 0.9, 0.8, 1.0}, {kInf, 0.98, 0.8, 2.0}};
  const LateralSlab scaled[] = {{0.5, 0.9, 0.8, 0.5}, {kInf, 0.98, 0.8, 1.0}};
  const LateralSlab uniform[] = {{0.5, 0.9, 0.8, 1.0}, {kInf, 0.98, 0.8, 1.0}};
  const double r = lateral_stack_response(slabs, nullptr, 1.0, {12, 16}).reflectance;
  EXPECT_NEAR(lateral_stack_response(scaled, nullptr, 0.5, {12, 16}).reflectance, r, 1e-10 * r);
  EXPECT_GT(r, lateral_stack_response(uniform, nullptr, 1.0, {12, 16}).reflectance);
  EXPECT_NEAR(lateral_stack_response(slabs, nullptr, 0.0, {12, 16}).reflectance,
              lateral_stack_response(uniform, nullptr, 0.0, {12, 16}).reflectance, 1e-12);
}

TEST(LateralFrequencyResponse, FallsWithFrequencyAndRefusesBadInput) {
  double previous = 1.0;
  for (const double k : {0.0, 0.1, 0.5, 2.0, 8.0}) {
    const double r = open_layer_lateral_response(kInf, 0.99, 0.8, k).reflectance;
    EXPECT_LT(r, previous) << k;
    EXPECT_GT(r, 0.0) << k;
    previous = r;
  }
  // Conservative scattering (§21.18): a white half-space returns all of the beam at k = 0 (within the 5e-9 that the
  // operator's clamped albedo leaves), and less at k > 0.
  const double white = open_layer_lateral_response(kInf, 1.0, 0.8, 0.0).reflectance;
  EXPECT_NEAR(white, 1.0, 1e-8);
  EXPECT_LT(open_layer_lateral_response(kInf, 1.0, 0.8, 0.1).reflectance, white);
  EXPECT_THROW(open_layer_lateral_response(1.0, 1.5, 0.8, 0.5), std::invalid_argument);
  EXPECT_THROW(open_layer_lateral_response(1.0, 0.5, 0.8, -1.0), std::invalid_argument);
  EXPECT_THROW(open_layer_lateral_response(-1.0, 0.5, 0.8, 1.0), std::invalid_argument);
  EXPECT_EQ(open_layer_lateral_response(0.0, 0.5, 0.8, 1.0).reflectance, 0.0);
}

}  // namespace
}  // namespace skinlayer
