// Rough interfaces between the slabs of a stack in the profile (docs/model.md §21.16): at k = 0 the stack solver's
// subsurface reflectance, against the walk, which crosses the interface facet by facet, and what is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/solve/resolution.h"
#include "core/solver.h"
#include "core/spatial/lateral_top_interface.h"
#include "core/spatial/layer_profile.h"
#include "tests/core/spatial/profile_against_walk.h"
#include "tests/core/spatial/rough_top_layers.h"

namespace skinlayer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A rough top over a layer of tau 1, an interface into a denser half-space below it (in mm when mu_t is given).
Material faced_stack(double upper_extinction, double lower_extinction) {
  Material m = test::rough_top_layer(1.0, 0.35, 0.9, 0.8);
  m.extinction = upper_extinction;
  m.below = {StackedLayer{kInf, 0.99, 0.8, LayerInterface{0.3, 1.1}, lower_extinction}};
  return m;
}

// The annuli add up to R(0), and R(0) plus the top's own multiply scattered reflection is the stack solver's
// subsurface reflectance at normal incidence: the same interface operators on the same nodes, projected on the
// azimuth samples of the solver's albedo (its mode 0 alone; with the profile's 97 against its 49 they differ by 8e-6).
TEST(InternalFacesProfile, PowersAddUpToTheStacksDirectionalAlbedo) {
  Material m = faced_stack(1.0, 2.0);
  m.sigma = 0.8;  // rough enough for the solver on 12 nodes (it asks for 6 / sigma)
  m.below.front().interface->sigma = 0.6;
  m.ordinates = 12;
  std::vector<double> edges = {0.0};
  for (double r = 0.05; r < 150.0; r *= 1.25) edges.push_back(r);
  LayerProfileOptions options = test::profile_test_options();
  SolveOptions mode_zero;
  mode_zero.max_modes = 1;
  options.interface_azimuths = choose_resolution(m, mode_zero).interface_azimuths;
  const LayerProfile profile = layer_profile(profile_layer(m), edges, options);
  double power = 0.0;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    power += profile.reflectance[i] * kPi * (edges[i + 1] * edges[i + 1] - edges[i] * edges[i]);
  }
  const double theta[] = {0.0};
  const DirectionalAlbedo albedo = directional_albedo(m, theta).front();
  const double surface = lateral_top_interface(top_interface(m), 12, 16, Incidence::Normal, options.interface_azimuths)
                             .surface_multiple_reflectance;
  std::printf("  through r < %.1f: %.8f   R(0): %.8f   solver less the surface's: %.8f\n", edges.back(), power,
              profile.total_reflectance, albedo.reflectance_subsurface - surface);
  EXPECT_NEAR(power, profile.total_reflectance, 1e-6);
  EXPECT_NEAR(profile.total_reflectance, albedo.reflectance_subsurface - surface, 1e-6);
}

// In millimetres: 0.05 mm at mu_t 20/mm over an interface (eta 1.1, sigma 0.3) into a half-space at 40/mm.
TEST(InternalFacesProfile, StackWithAnInterfaceMatchesTheWalk) {
  const Material m = faced_stack(20.0, 40.0);
  test::expect_profile_matches_the_walk(
      profile_layer(m), m, test::profile_test_options(),
      {0.0, 0.0025, 0.005, 0.01, 0.02, 0.035, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3, 0.4, 0.6, 0.8, 1.2, 1.6}, 20.0);
}

TEST(InternalFacesProfile, WhatItCannotTakeYetIsRefused) {
  ProfileLayer layer = profile_layer(faced_stack(1.0, 2.0));
  const double radii[] = {1.0};
  LayerProfileOptions coarse;  // what is taken need not be accurate here
  coarse.resolution = {6, 4};
  coarse.frequencies = 8;
  EXPECT_GT(layer_profile_at(layer, radii, coarse).reflectance.front(), 0.0);
  layer.incidence = Incidence::Diffuse;
  EXPECT_GT(layer_profile_at(layer, radii, coarse).reflectance.front(), 0.0);
  layer.below.front().tau = 2.0;  // a finite stack: its transmittance through the interface is not computed yet
  EXPECT_THROW(layer_profile_at(layer, radii, coarse), ParameterError);
  LayerProfileOptions reflected = coarse;
  reflected.reflectance_only = true;
  EXPECT_GT(layer_profile_at(layer, radii, reflected).reflectance.front(), 0.0);
  layer.incidence = Incidence::Normal;
  layer.top.reset();  // the collimated beam of an open top would reach the interface unscattered
  EXPECT_THROW(layer_profile_at(layer, radii, reflected), ParameterError);
  layer.faces = {std::nullopt, std::nullopt};  // one per slab below the first
  EXPECT_THROW(layer_profile_at(layer, radii, reflected), std::invalid_argument);
}

}  // namespace
}  // namespace skinlayer
