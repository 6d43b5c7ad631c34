// Exit positions in the Monte Carlo reference (core/reference/monte_carlo.h, RadialBin): the reference that the
// spatially resolved profiles will be checked against, itself checked here against a closed form and two identities.
//
// Single scattering under an open top has a closed form. A pencil beam enters a semi-infinite, index-matched medium
// at normal incidence and is scattered once at depth z (density e^-z). Scattered towards the top at polar angle
// theta (mu = cos theta), it leaves at r = z tan(theta) after a path z / mu. Per unit area of the top face:
//   R1(r) = Omega int_0^inf e^-z p(-z/l) e^-l z / l^3 dz,   l = sqrt(r^2 + z^2),
// with p the Henyey-Greenstein phase function in 1/sr (the scattering angle's cosine is -z/l: the beam travels down).
// Over an annulus, with r = z tan(theta), z / l^3 2 pi r dr = 2 pi sin(theta) d theta, so
//   int_{r0}^{r1} 2 pi r R1(r) dr = Omega int_0^inf e^-z int_{atan(r0/z)}^{atan(r1/z)} p(-cos th) e^{-z/cos th}
//                                     2 pi sin(th) d th dz,
// which Gauss-Legendre rules integrate to better than 1e-6 here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/reference/monte_carlo.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

double henyey_greenstein(double g, double cos_theta) {  // 1/sr
  return (1.0 - g * g) / (4.0 * kPi * std::pow(1.0 + g * g - 2.0 * g * cos_theta, 1.5));
}

// int_{r0}^{r1} 2 pi r R1(r) dr for the single-scattered light of a matched, semi-infinite layer (lengths in mean
// free paths), by the (z, theta) form above: panels in z, each with a Gauss-Legendre rule in z and in theta.
double single_scattering_through_annulus(double albedo, double g, double r0, double r1) {
  const double panels[] = {0.0, 0.02, 0.1, 0.3, 1.0, 2.5, 5.0, 10.0, 20.0, 45.0};
  double total = 0.0;
  for (std::size_t p = 0; p + 1 < std::size(panels); ++p) {
    const QuadratureRule zs = gauss_legendre(48, panels[p], panels[p + 1]);
    for (std::size_t i = 0; i < zs.nodes.size(); ++i) {
      const double z = zs.nodes[i];
      const QuadratureRule thetas = gauss_legendre(48, std::atan(r0 / z), std::atan(r1 / z));
      double inner = 0.0;
      for (std::size_t j = 0; j < thetas.nodes.size(); ++j) {
        const double th = thetas.nodes[j];
        inner += thetas.weights[j] * henyey_greenstein(g, -std::cos(th)) * std::exp(-z / std::cos(th)) * 2.0 * kPi *
                 std::sin(th);
      }
      total += zs.weights[i] * std::exp(-z) * inner;
    }
  }
  return albedo * total;
}

std::vector<RadialBin> annuli(ExitSide side, std::vector<double> edges) {
  std::vector<RadialBin> bins;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) bins.push_back({side, edges[i], edges[i + 1]});
  return bins;
}

Material open_half_space(double albedo, double g) {
  Material m;
  m.eta = 1.0;  // no top interface: the beam enters at r = 0 unrefracted
  m.tau = std::numeric_limits<double>::infinity();
  m.albedo = albedo;
  m.g = g;
  return m;
}

MonteCarloOptions single_scattering(std::uint64_t paths) {
  MonteCarloOptions options;
  options.paths = paths;
  options.seed = 7;
  options.max_scattering_order = 1;
  return options;
}

// Point by point, the peak at the beam included: every annulus from 0.005 to 8 mean free paths within 4 standard
// errors of the closed form, for isotropic and forward scattering; and the annuli add up to the total, which is
// Omega (1 - ln 2) / 2 for isotropic scattering.
TEST(MonteCarloPositions, SingleScatteringMatchesItsClosedFormInEveryAnnulus) {
  const std::vector<double> edges = {0.0, 0.005, 0.02, 0.05, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 5.0, 8.0};
  const std::vector<RadialBin> bins = annuli(ExitSide::Reflected, edges);
  for (const double g : {0.0, 0.8}) {
    const Material material = open_half_space(0.9, g);
    const MonteCarloResult mc = simulate_layer(material, 0.0, {}, single_scattering(2'000'000), bins);
    EXPECT_FALSE(mc.lengths_in_mm);
    ASSERT_EQ(mc.radial_bins.size(), bins.size());
    double through_annuli = 0.0;
    for (std::size_t b = 0; b < bins.size(); ++b) {
      const double expected = single_scattering_through_annulus(0.9, g, bins[b].r_min, bins[b].r_max) / bins[b].area();
      const MonteCarloEstimate& got = mc.radial_bins[b];
      std::printf("  g %.1f  r [%5.3f, %5.3f)  MC %.6g +- %.2g  closed form %.6g  (%+.2f SE)\n", g, bins[b].r_min,
                  bins[b].r_max, got.value, got.standard_error, expected, (got.value - expected) / got.standard_error);
      EXPECT_LT(std::abs(got.value - expected), 4.0 * got.standard_error) << "g " << g << " annulus " << b;
      through_annuli += got.value * bins[b].area();
    }
    // Light leaving beyond 8 mean free paths is what the annuli miss.
    const double beyond = single_scattering_through_annulus(0.9, g, 8.0, 1e6);
    EXPECT_NEAR(through_annuli + beyond, mc.reflectance_subsurface.value,
                4.0 * mc.reflectance_subsurface.standard_error);
    if (g == 0.0) {
      EXPECT_NEAR(single_scattering_through_annulus(0.9, 0.0, 0.0, 1e6), 0.9 * (1.0 - std::log(2.0)) / 2.0, 1e-6);
    }
  }
}

// With every layer's extinction, radii are in mm: scaling mu_t by k shrinks the profile by k and raises it by k^2,
// path for path (the same seed walks the same optical paths).
TEST(MonteCarloPositions, ExtinctionTurnsMeanFreePathsIntoMillimetres) {
  Material slab;  // the default rough top and bottom, tau 1.6, forward scattering
  slab.albedo = 0.95;
  MonteCarloOptions options;
  options.paths = 200'000;
  options.seed = 3;
  options.threads = 1;
  std::vector<double> edges = {0.0, 0.1, 0.3, 0.6, 1.0, 2.0, 4.0};
  std::vector<RadialBin> in_mfp = annuli(ExitSide::Reflected, edges);
  for (const RadialBin& bin : annuli(ExitSide::Transmitted, edges)) in_mfp.push_back(bin);
  const MonteCarloResult unitless = simulate_layer(slab, 0.3, {}, options, in_mfp);

  constexpr double kExtinction = 8.0;  // 1/mm: a mean free path of 0.125 mm
  slab.extinction = kExtinction;
  std::vector<RadialBin> in_mm = in_mfp;
  for (RadialBin& bin : in_mm) {
    bin.r_min /= kExtinction;
    bin.r_max /= kExtinction;
  }
  const MonteCarloResult mm = simulate_layer(slab, 0.3, {}, options, in_mm);
  EXPECT_TRUE(mm.lengths_in_mm);
  ASSERT_EQ(mm.radial_bins.size(), in_mm.size());
  double transmitted = 0.0;
  for (std::size_t b = 0; b < in_mm.size(); ++b) {
    EXPECT_GT(unitless.radial_bins[b].value, 0.0) << b;
    EXPECT_NEAR(mm.radial_bins[b].value, kExtinction * kExtinction * unitless.radial_bins[b].value,
                1e-9 * mm.radial_bins[b].value)
        << b;
    if (in_mm[b].side == ExitSide::Transmitted) transmitted += mm.radial_bins[b].value * in_mm[b].area();
  }
  // The transmitted annuli hold the scattered transmission within 4 mm... most of it, and never more than all.
  EXPECT_LE(transmitted, mm.transmittance.value - mm.transmittance_direct.value + 1e-12);
  EXPECT_GT(transmitted, 0.8 * (mm.transmittance.value - mm.transmittance_direct.value));
}

TEST(MonteCarloPositions, AStackNeedsEveryLayersExtinctionAndAnnuliMustBeOrdered) {
  Material stack;
  stack.extinction = 10.0;
  stack.below = {StackedLayer{std::numeric_limits<double>::infinity(), 0.9, 0.5, std::nullopt}};
  MonteCarloOptions options;
  options.paths = 10;
  const std::vector<RadialBin> bins = annuli(ExitSide::Reflected, {0.0, 1.0});
  try {
    simulate_layer(stack, 0.0, {}, options, bins);
    ADD_FAILURE() << "a stack without every layer's extinction was accepted";
  } catch (const ParameterError& error) {
    EXPECT_NE(std::string(error.what()).find("1 of its 2 layers have none"), std::string::npos) << error.what();
  }
  // Without annuli the stack needs no lengths; with every extinction it takes them.
  EXPECT_NO_THROW(simulate_layer(stack, 0.0, {}, options));
  stack.below[0].extinction = 5.0;
  EXPECT_TRUE(simulate_layer(stack, 0.0, {}, options, bins).lengths_in_mm);
  const RadialBin inverted{ExitSide::Reflected, 1.0, 0.5};
  EXPECT_THROW(simulate_layer(stack, 0.0, {}, options, std::span(&inverted, 1)), ParameterError);
}

}  // namespace
}  // namespace skinlayer
