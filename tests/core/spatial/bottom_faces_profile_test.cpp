// A finite stack's rough bottom face and Lambertian base in the profile (docs/model.md §21.17): at k = 0 the BSDF
// solver's subsurface reflectance and transmittance, and against the walk, which crosses the bottom facet by facet.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/spatial/layer_profile.h"
#include "tests/core/spatial/profile_against_walk.h"
#include "tests/core/spatial/profile_totals.h"
#include "tests/core/spatial/rough_top_layers.h"

namespace skinlayer {
namespace {

// The paper's layer (tau 1.6, T 0.2; top sigma 0.5, eta 1.4) with albedo 0.95 over air through a rough bottom.
Material rough_bottomed_layer() {
  Material m = test::rough_top_layer(-std::log(0.2), 0.5, 0.95, 0.8);
  m.bottom = Bottom{BottomKind::Air, 0.5, 1.4, 0.0};
  return m;
}

Material lambert_based_layer() {
  Material m = test::rough_top_layer(1.0, 0.5, 0.9, 0.8);
  m.bottom = Bottom{BottomKind::Lambert, std::nullopt, std::nullopt, 0.7};
  return m;
}

TEST(BottomFacesProfile, RoughBottomTotalsAreTheSolvers) {
  test::expect_totals_match_the_solver(rough_bottomed_layer());
}

TEST(BottomFacesProfile, LambertBaseTotalsAreTheSolvers) {
  test::expect_totals_match_the_solver(lambert_based_layer());
}

const std::vector<double> kEdges = {0.0, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0};

// Against the walk on the 24 nodes the command takes for light through a finite stack (12 leave the Lambertian base's
// central annuli 4-6% off), under the default interfaces (MicrofacetModel::Multiple) and under the paper's. At the
// paper's sigma 0.5 between two rough faces much of the light is trapped by total internal reflection, and what the
// microsurface scatters more than once carries it sideways (docs/model.md §3.2b, §21.17).
TEST(BottomFacesProfile, RoughBottomMatchesTheWalk) {
  const Material m = rough_bottomed_layer();
  test::expect_profile_matches_the_walk(profile_layer(m), m, test::transmitted_radiance_options(), kEdges);
}

TEST(BottomFacesProfile, SharperRoughBottomMatchesTheWalk) {
  Material m = rough_bottomed_layer();
  m.sigma = 0.2;
  m.bottom.sigma = 0.2;
  test::expect_profile_matches_the_walk(profile_layer(m), m, test::transmitted_radiance_options(), kEdges);
}

TEST(BottomFacesProfile, PapersRoughBottomMatchesTheWalkUnderItsInterfaces) {
  Material m = rough_bottomed_layer();
  m.microfacet = MicrofacetModel::Single;
  test::expect_profile_matches_the_walk(profile_layer(m), m, test::transmitted_radiance_options(), kEdges);
}

TEST(BottomFacesProfile, LambertBaseMatchesTheWalk) {
  const Material m = lambert_based_layer();
  test::expect_profile_matches_the_walk(profile_layer(m), m, test::transmitted_radiance_options(), kEdges);
}

TEST(BottomFacesProfile, ACollimatedBeamOntoARoughBottomIsRefused) {
  Material m = rough_bottomed_layer();
  m.eta = 1.0;  // an open top: the beam reaches the bottom collimated
  const double edges[] = {0.0, 1.0};
  LayerProfileOptions coarse;
  coarse.resolution = {6, 4};
  coarse.frequencies = 8;
  ProfileLayer layer{m.tau, m.albedo, m.g};
  layer.rough_bottom = bottom_interface(m);
  EXPECT_THROW(layer_profile(layer, edges, coarse), ParameterError);
  layer.rough_bottom.reset();
  layer.lambert_bottom = 0.5;
  EXPECT_THROW(layer_profile(layer, edges, coarse), ParameterError);
}

// The unscattered bounce through an interface between layers is not built: refused, even for the reflectance alone.
TEST(BottomFacesProfile, ABottomUnderAnInterfaceBetweenLayersIsRefused) {
  Material m = lambert_based_layer();
  m.extinction = 1.0;
  m.below = {StackedLayer{1.0, 0.9, 0.8, LayerInterface{0.3, 1.1}, 1.0}};
  const double edges[] = {0.0, 1.0};
  LayerProfileOptions coarse;
  coarse.resolution = {6, 4};
  coarse.frequencies = 8;
  coarse.reflectance_only = true;
  EXPECT_THROW(layer_profile(profile_layer(m), edges, coarse), ParameterError);
}

}  // namespace
}  // namespace skinlayer
