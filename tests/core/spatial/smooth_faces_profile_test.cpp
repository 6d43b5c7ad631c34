// Smooth (Fresnel) faces in the profile (docs/model.md §21.14): the closed form of a collimated beam's single
// scattering against the solve's own, and MCML's published three-layer sample, whose faces are smooth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/conventions.h"
#include "core/series/quadrature.h"
#include "core/spatial/lateral_frequency_response.h"
#include "core/spatial/lateral_top_interface.h"
#include "core/spatial/layer_profile.h"
#include "core/spatial/rough_top_single_scattering.h"
#include "tests/core/reference_csv.h"
#include "tests/core/spatial/mcml_agreement.h"

namespace skinlayer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The collimated beam's single scattering in closed form (entry straight down, exit on the nodes through the smooth
// top) is, at k = 0, the solve's first order in the albedos, in a stack whose slabs differ in extinction.
TEST(SmoothFacesProfile, CollimatedSingleScatteringClosedFormIsTheSolvesFirstOrder) {
  const LateralTopInterface top = smooth_top_interface(1.37, 12, 16);
  EXPECT_NEAR(top.collimated, 1.0 - std::pow(0.37 / 2.37, 2), 1e-12);
  const LateralSlab slabs[] = {{2.0, 0.9, 0.8, 1.0}, {kInf, 0.95, 0.5, 0.3}};
  const double solved = collimated_single_scattering_response(slabs, &top, 0.0, {12, 4}).reflectance;
  const double closed = rough_top_single_scattered_power(slabs, top, 12, 0.0, kInf);
  EXPECT_NEAR(closed, solved, 1e-9 * solved);
  // And its density integrates to its annulus power across the slabs' face.
  const double r0 = 0.2, r1 = 3.0;
  double integral = 0.0;
  const QuadratureRule rule = gauss_legendre(16, 0.0, 1.0);
  for (int p = 0; p < 64; ++p) {
    const double a = r0 + (r1 - r0) * p / 64.0, b = r0 + (r1 - r0) * (p + 1) / 64.0;
    integral += integrate_mapped(
        rule, a, b, [&](double r) { return 2.0 * kPi * r * rough_top_single_scattered_density(slabs, top, 12, r); });
  }
  const double power = rough_top_single_scattered_power(slabs, top, 12, r0, r1);
  EXPECT_NEAR(integral, power, 1e-4 * power);
}

// One face's profile (1/mfp^2) against MCML's rows of `table` (1/mm^2, in 0.1 mm annuli; 10^6 photons), from
// from_mm on.
void expect_matches_mcml(const char* face, const std::vector<double>& profile, const test::CsvTable& table, double mu_t,
                         double from_mm = 0.0) {
  std::vector<double> edges = {0.0}, got, expected;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    edges.push_back(table.number(i, "r_outer_mm"));
    expected.push_back(table.number(i, "per_mm2"));
    got.push_back(profile[i] * mu_t * mu_t);  // 1/mfp^2 -> 1/mm^2
  }
  test::expect_within_mcml_noise(face, got, expected, edges, 1e6, true, from_mm);
}

// MCML 1.2.2's published sample (tests/reference/README.md): three layers of n 1.37 between air above and below,
// 0.1, 0.1 and 0.2 cm thick, mu_t 101, 11 and 12 /cm, albedos 100/101, 10/11 and 10/12, g 0.9, 0 and 0.7. In the
// first layer's mean free paths the slabs are tau 10.1, 1.1 and 2.4 with relative extinctions 1, 11/101 and 12/101.
// Its diffuse reflectance is 0.237544 and its transmittance 0.0964896 (of which the direct beam is 1.2e-6); its
// Rd_r and Tt_r are in 0.1 mm annuli.
TEST(SmoothFacesProfile, AgreesWithMcmlsPublishedThreeLayerSample) {
  const test::CsvTable reflected = test::read_reference("mcml_sample_three_layers.csv");
  const test::CsvTable transmitted = test::read_reference("mcml_sample_three_layers_transmitted.csv");
  constexpr double kMuT = 10.1;  // 1/mm: the first layer's extinction, 101 /cm
  std::vector<double> edges_mfp = {0.0};
  for (std::size_t row = 0; row < reflected.rows.size(); ++row) {
    edges_mfp.push_back(reflected.number(row, "r_outer_mm") * kMuT);
    ASSERT_EQ(transmitted.number(row, "r_outer_mm"), reflected.number(row, "r_outer_mm"));
  }
  ProfileLayer layer{10.1, 100.0 / 101.0, 0.9};
  layer.below = {LateralSlab{1.1, 10.0 / 11.0, 0.0, 11.0 / 101.0}, LateralSlab{2.4, 10.0 / 12.0, 0.7, 12.0 / 101.0}};
  layer.smooth_top = 1.37;
  layer.smooth_bottom = 1.0 / 1.37;
  LayerProfileOptions options;
  // 16 nodes: the light trapped between the smooth faces by total internal reflection travels far in the weakly
  // scattering lower layers, and 12 nodes resolve its grazing directions too coarsely (the tail beyond 3 mm then
  // runs 10% high). 8 modes change the profile by 0.4% at most here.
  options.resolution = {16, 8};
  options.frequencies = 32;
  const LayerProfile profile = layer_profile(layer, edges_mfp, options);
  std::printf("  diffuse reflectance: profile %.5f  MCML 0.237544\n", profile.total_reflectance);
  std::printf("  transmittance: profile %.5f  MCML 0.0964884\n", profile.total_transmittance);
  EXPECT_NEAR(profile.total_reflectance, 0.237544, 0.01 * 0.237544);
  EXPECT_NEAR(profile.total_transmittance, 0.0964884, 0.01 * 0.0964884);
  expect_matches_mcml("R", profile.reflectance, reflected, kMuT);
  // The transmittance beyond 0.7 mm. Nearer the axis the ordinates' ray effect shows: the light leaving the dense
  // first layer crosses 3 mm of sparse ones (tau 3.5) partly unscattered, along the nodes alone, and the node nearest
  // the normal (5.9 degrees at 16) lands 0.31 mm out. So the profile dips where MCML is flat: 65% low in the central
  // 0.1 mm at 16 nodes, 49% at 32 (docs/model.md §21.15).
  expect_matches_mcml("T", profile.transmittance, transmitted, kMuT, 0.7);
}

}  // namespace
}  // namespace skinlayer
