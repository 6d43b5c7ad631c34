// The profile of a half-space under a rough top (core/spatial/layer_profile.h with ProfileLayer::top): against the
// Monte Carlo reference, whose walk crosses the same rough interface facet by facet, against the BSDF's subsurface
// reflectance, and its point and annulus forms against each other.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/reference/monte_carlo.h"
#include "core/series/quadrature.h"
#include "core/solver.h"
#include "core/spatial/lateral_top_interface.h"
#include "core/spatial/layer_profile.h"
#include "tests/core/index_matched_slab.h"
#include "tests/core/spatial/profile_against_walk.h"
#include "tests/core/spatial/rough_top_layers.h"

namespace skinlayer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Material rough_half_space(double sigma, double albedo, double g) {
  return test::rough_top_layer(kInf, sigma, albedo, g);
}

const std::vector<double> kEdges = {0.0, 0.05, 0.1, 0.2, 0.35, 0.5,  0.75, 1.0, 1.5,
                                    2.0, 3.0,  4.0, 6.0, 8.0,  12.0, 16.0, 24.0};

// Skin-like: a weakly absorbing, forward-scattering half-space under a fairly smooth top.
TEST(RoughTopProfile, ForwardScatteringHalfSpaceMatchesTheWalk) {
  const Material m = rough_half_space(0.3, 0.99, 0.8);
  test::expect_profile_matches_the_walk(profile_layer(m), m, test::profile_test_options(), kEdges);
}

// A rougher top over a more absorbing, less forward medium: the light stays near the beam.
TEST(RoughTopProfile, RoughTopOverAnAbsorbingHalfSpaceMatchesTheWalk) {
  const Material m = rough_half_space(0.8, 0.9, 0.5);
  test::expect_profile_matches_the_walk(profile_layer(m), m, test::profile_test_options(), kEdges);
}

// A skin-like stack in millimetres: a 0.08 mm layer (mu_t 20/mm, Omega 0.9) over a half-space of twice its extinction
// (Omega 0.99), g 0.8 in both, under a sigma 0.35 top. The walk takes each layer's mu_t; the profile takes the lower
// layer's relative to the upper's.
TEST(RoughTopProfile, TwoLayerStackInMillimetresMatchesTheWalk) {
  Material m = test::index_matched_slab(1.6, 0.9, 0.8);
  m.eta = 1.4;
  m.sigma = 0.35;
  m.extinction = 20.0;
  m.below = {StackedLayer{kInf, 0.99, 0.8, std::nullopt, 40.0}};
  test::expect_profile_matches_the_walk(
      profile_layer(m), m, test::profile_test_options(),
      {0.0, 0.0025, 0.005, 0.01, 0.02, 0.035, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3, 0.4, 0.6, 0.8, 1.2, 1.6}, 20.0);
}

// The annuli's powers through all space add up to R(0), and R(0) plus the top's own multiply scattered reflection
// (which leaves at the entry point) is the BSDF's subsurface reflectance at normal incidence, on the same ordinates.
TEST(RoughTopProfile, PowersAddUpToTheDirectionalAlbedo) {
  Material m = rough_half_space(0.5, 0.95, 0.6);
  m.ordinates = 12;
  std::vector<double> edges = {0.0};
  for (double r = 0.05; r < 120.0; r *= 1.25) edges.push_back(r);
  const LayerProfile profile = layer_profile(profile_layer(m), edges, test::profile_test_options());
  double power = 0.0;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    power += profile.reflectance[i] * kPi * (edges[i + 1] * edges[i + 1] - edges[i] * edges[i]);
  }
  const double theta[] = {0.0};
  const DirectionalAlbedo albedo = directional_albedo(m, theta).front();
  const double surface = lateral_top_interface(top_interface(m), 12, 16).surface_multiple_reflectance;
  std::printf("  through r < %.1f: %.8f   R(0): %.8f   solver less the surface's: %.8f\n", edges.back(), power,
              profile.total_reflectance, albedo.reflectance_subsurface - surface);
  EXPECT_NEAR(power, profile.total_reflectance, 1e-6);
  EXPECT_NEAR(profile.total_reflectance, albedo.reflectance_subsurface - surface, 1e-6);
}

// Point values averaged over an annulus (Gauss-Legendre in r) are the annulus's value.
TEST(RoughTopProfile, PointValuesAverageToTheAnnuli) {
  const ProfileLayer layer = profile_layer(rough_half_space(0.4, 0.95, 0.7));
  const std::vector<double> edges = {0.1, 0.3, 1.0, 3.0, 8.0};
  const QuadratureRule rule = gauss_legendre(24, 0.0, 1.0);
  std::vector<double> radii;
  for (std::size_t a = 0; a + 1 < edges.size(); ++a) {
    for (const double t : rule.nodes) radii.push_back(edges[a] + (edges[a + 1] - edges[a]) * t);
  }
  const LayerProfile points = layer_profile_at(layer, radii, test::profile_test_options());
  const LayerProfile annuli = layer_profile(layer, edges, test::profile_test_options());
  for (std::size_t a = 0; a + 1 < edges.size(); ++a) {
    const double r0 = edges[a], r1 = edges[a + 1];
    double reflected = 0.0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
      const std::size_t at = a * rule.nodes.size() + i;
      reflected += rule.weights[i] * (r1 - r0) * 2.0 * kPi * radii[at] * points.reflectance[at];
    }
    const double mean = reflected / (kPi * (r1 * r1 - r0 * r0));
    EXPECT_NEAR(mean, annuli.reflectance[a], 1e-5 * annuli.reflectance[a] + 1e-7) << r0;
    EXPECT_EQ(points.transmittance[a], 0.0);
  }
}

// Diffuse light is the hemispherical average of the beams: at k = 0, under a rough top, R(0) plus the surface's
// multiply scattered reflection is the average of the solver's subsurface reflectance over the same incident cosines.
TEST(RoughTopProfile, DiffuseIncidenceAtZeroFrequencyIsTheHemisphericalAverage) {
  Material m = rough_half_space(0.5, 0.95, 0.7);
  m.ordinates = 12;
  const QuadratureRule cosines = diffuse_incidence_cosines();
  std::vector<double> theta;
  for (const double mu : cosines.nodes) theta.push_back(std::acos(mu));
  const std::vector<DirectionalAlbedo> albedo = directional_albedo(m, theta);
  double average = 0.0;
  for (std::size_t q = 0; q < theta.size(); ++q) average += cosines.weights[q] * albedo[q].reflectance_subsurface;
  const LateralTopInterface top = lateral_top_interface(top_interface(m), 12, 4, Incidence::Diffuse);
  const LateralSlab half_space[] = {{kInf, 0.95, 0.7}};
  const double at_zero = lateral_stack_response(half_space, &top, 0.0, {12, 4}).reflectance;
  EXPECT_NEAR(at_zero + top.surface_multiple_reflectance, average, 1e-6);
  // Through no interface the light enters as node radiance 1/pi, not as beams: the same average within the
  // ordinates' discretization of each beam's first scattering.
  const Material open = test::index_matched_slab(kInf, 0.95, 0.7);
  const std::vector<DirectionalAlbedo> open_albedo = directional_albedo(open, theta);
  double open_average = 0.0;
  for (std::size_t q = 0; q < theta.size(); ++q)
    open_average += cosines.weights[q] * open_albedo[q].reflectance_subsurface;
  const LateralTopInterface none = open_top_interface(12, 4, Incidence::Diffuse);
  EXPECT_NEAR(lateral_stack_response(half_space, &none, 0.0, {12, 4}).reflectance, open_average, 2e-3 * open_average);
}

// The walk lit at the cosines of an 8-point rule, each run weighted by 2 mu w: diffuse light's profile under a rough
// top, annulus by annulus, within 2% or 3 standard errors above 1e-3 of the peak.
TEST(RoughTopProfile, DiffuseIncidenceMatchesTheWalkAveragedOverTheHemisphere) {
  const Material m = rough_half_space(0.4, 0.98, 0.8);
  ProfileLayer layer = profile_layer(m);
  layer.incidence = Incidence::Diffuse;
  const std::vector<double> edges = {0.0, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0};
  const LayerProfile profile = layer_profile(layer, edges, test::profile_test_options());
  std::vector<RadialBin> bins;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) bins.push_back({ExitSide::Reflected, edges[i], edges[i + 1]});
  const QuadratureRule rule = gauss_legendre(8, 0.0, 1.0);
  std::vector<double> value(bins.size(), 0.0), variance(bins.size(), 0.0);
  for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
    MonteCarloOptions options;
    options.paths = 200'000;
    options.seed = 20 + q;
    const MonteCarloResult mc = simulate_layer(m, std::acos(rule.nodes[q]), {}, options, bins);
    const double weight = 2.0 * rule.nodes[q] * rule.weights[q];
    for (std::size_t i = 0; i < bins.size(); ++i) {
      value[i] += weight * mc.radial_bins[i].value;
      variance[i] += weight * weight * mc.radial_bins[i].standard_error * mc.radial_bins[i].standard_error;
    }
  }
  double peak = 0.0;
  for (const double v : profile.reflectance) peak = std::max(peak, v);
  for (std::size_t i = 0; i < bins.size(); ++i) {
    const double se = std::sqrt(variance[i]), diff = profile.reflectance[i] - value[i];
    std::printf("  R [%5.2f, %5.2f)  profile %.4e  walk %.4e +- %.1e  (%+.2f%%, %+.2f SE)\n", edges[i], edges[i + 1],
                profile.reflectance[i], value[i], se, 100.0 * diff / value[i], diff / se);
    if (profile.reflectance[i] < 1e-3 * peak) continue;
    EXPECT_TRUE(std::abs(diff) <= 0.02 * value[i] || std::abs(diff) <= 3.0 * se) << edges[i];
  }
}

// Fewer modes at low frequencies (LayerProfileOptions::adaptive_modes) leave a skin-like stack's profile as it is.
TEST(RoughTopProfile, AdaptiveModesLeaveTheProfile) {
  ProfileLayer layer = profile_layer(rough_half_space(0.4, 0.95, 0.8));
  layer.tau = 1.5;
  layer.below = {LateralSlab{kInf, 0.99, 0.8, 0.6}};
  const double radii[] = {0.1, 0.5, 2.0, 8.0, 20.0};
  LayerProfileOptions all_modes = test::profile_test_options();
  all_modes.adaptive_modes = false;
  const LayerProfile fixed = layer_profile_at(layer, radii, all_modes);
  const LayerProfile adaptive = layer_profile_at(layer, radii, test::profile_test_options());
  for (std::size_t i = 0; i < std::size(radii); ++i) {
    EXPECT_NEAR(adaptive.reflectance[i], fixed.reflectance[i], 1e-5 * fixed.reflectance[i]) << radii[i];
  }
}

TEST(RoughTopProfile, WhatItCannotTakeYetIsRefused) {
  ProfileLayer layer = profile_layer(rough_half_space(0.4, 0.95, 0.7));
  layer.tau = 2.0;
  const double radii[] = {1.0};
  LayerProfileOptions coarse;  // what is taken need not be accurate here
  coarse.resolution = {6, 4};
  coarse.frequencies = 8;
  // A finite layer and a finite stack under a rough top, open or in diffuse light, transmit (§21.15).
  EXPECT_GT(layer_profile_at(layer, radii, coarse).transmittance.front(), 0.0);
  layer.below = {LateralSlab{3.0, 0.9, 0.8, 1.0}};
  EXPECT_GT(layer_profile_at(layer, radii, coarse).transmittance.front(), 0.0);
  layer.incidence = Incidence::Diffuse;
  EXPECT_GT(layer_profile_at(layer, radii, coarse).transmittance.front(), 0.0);
  LayerProfileOptions reflected = coarse;
  reflected.reflectance_only = true;  // the transmittance left out when only the reflectance is asked for
  EXPECT_TRUE(layer_profile_at(layer, radii, reflected).transmittance.empty());
  // A smooth bottom under light that enters as radiance would send its unscattered rings back up: not yet.
  layer.smooth_bottom = 1.0 / 1.4;
  EXPECT_THROW(layer_profile_at(layer, radii, coarse), ParameterError);
  layer.incidence = Incidence::Normal;
  EXPECT_THROW(layer_profile_at(layer, radii, coarse), ParameterError);
  layer.top.reset();  // under an open top the beam stays collimated: taken
  EXPECT_GT(layer_profile_at(layer, radii, coarse).transmittance.front(), 0.0);
  layer.smooth_bottom.reset();
  layer.below.back().tau = kInf;
  layer.incidence = Incidence::Diffuse;
  layer.smooth_top = 1.4;  // diffuse light through a smooth top: not yet
  EXPECT_THROW(layer_profile_at(layer, radii, coarse), std::invalid_argument);
}

}  // namespace
}  // namespace skinlayer
