// The open layer's spatial profile (core/spatial/layer_profile.h) against the Monte Carlo reference's exit
// positions annulus by annulus (tests/core/spatial/profile_against_walk.h), against MCML and the diffusion dipole, and
// its single-scattering part against its own transform.
#include "core/spatial/layer_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/reference/diffusion_dipole.h"
#include "core/series/quadrature.h"
#include "core/spatial/single_scattering_profile.h"
#include "tests/core/index_matched_slab.h"
#include "tests/core/reference_csv.h"
#include "tests/core/spatial/mcml_agreement.h"
#include "tests/core/spatial/profile_against_walk.h"

namespace skinlayer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMcmlPhotons = 2e6;  // per case, tests/reference/README.md

// A weakly absorbing, forward-scattering half-space: light spreads to ~20 mean free paths.
TEST(LayerProfile, HalfSpaceMatchesTheWalkInEveryAnnulus) {
  test::expect_profile_matches_the_walk(
      {kInf, 0.99, 0.8}, test::index_matched_slab(kInf, 0.99, 0.8), test::profile_test_options(),
      {0.0, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0, 24.0});
}

// A slab: reflection and transmission, both peaked at the beam.
TEST(LayerProfile, SlabReflectionAndTransmissionMatchTheWalk) {
  test::expect_profile_matches_the_walk({2.0, 0.9, 0.5}, test::index_matched_slab(2.0, 0.9, 0.5),
                                        test::profile_test_options(),
                                        {0.0, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0});
}

// MCML 1.2.2 (Wang, Jacques & Zheng 1995), run on the same two open layers (tests/reference/README.md): an
// independent program's annuli, 0.5 mean free paths wide for the half-space and 0.1 for the slab. Where the profile
// exceeds 1e-3 of its peak, it agrees within 2% plus 3 times MCML's own noise, which for an annulus that 2e6
// photons leave through with power P is about 1/sqrt(2e6 P) relative (2% at r = 4 in the slab's thin annuli).
TEST(LayerProfile, AgreesWithMcmlsAnnuli) {
  const test::CsvTable mcml = test::read_reference("mcml_open_layers.csv");
  struct Case {
    std::string name;
    double tau, albedo, g;
  };
  for (const Case& c : {Case{"halfspace", kInf, 0.99, 0.8}, Case{"slab", 2.0, 0.9, 0.5}}) {
    for (const std::string side : {"reflectance", "transmittance"}) {
      std::vector<double> edges, expected;
      for (std::size_t row = 0; row < mcml.rows.size(); ++row) {
        if (mcml.text(row, "case") != c.name || mcml.text(row, "side") != side) continue;
        if (edges.empty()) edges.push_back(mcml.number(row, "r_inner_mfp"));
        edges.push_back(mcml.number(row, "r_outer_mfp"));
        expected.push_back(mcml.number(row, "per_mfp2"));
      }
      if (expected.empty()) continue;
      const LayerProfile profile = layer_profile({c.tau, c.albedo, c.g}, edges, test::profile_test_options());
      const std::vector<double>& got = side == "reflectance" ? profile.reflectance : profile.transmittance;
      test::expect_within_mcml_noise(c.name + " " + side, got, expected, edges, kMcmlPhotons);
    }
  }
}

// The profile at points, averaged over an annulus by quadrature in r, is the annulus's value: the J0 and J1 forms of
// the inverse transform, and single scattering's density and annulus forms, are independent quadratures of one
// integral. (Without the roll-off of the transform towards k_max, the J0 form's truncation made them differ by 1%.)
TEST(LayerProfile, PointValuesAverageToTheAnnuli) {
  const std::vector<double> edges = {0.2, 0.5, 1.0, 2.0, 5.0, 8.0};
  const QuadratureRule rule = gauss_legendre(24, 0.0, 1.0);
  std::vector<double> radii;
  for (std::size_t a = 0; a + 1 < edges.size(); ++a) {
    for (const double t : rule.nodes) radii.push_back(edges[a] + (edges[a + 1] - edges[a]) * t);
  }
  for (const double tau : {kInf, 1.5}) {
    const LayerProfile points = layer_profile_at({tau, 0.95, 0.7}, radii, test::profile_test_options());
    const LayerProfile annuli = layer_profile({tau, 0.95, 0.7}, edges, test::profile_test_options());
    for (std::size_t a = 0; a + 1 < edges.size(); ++a) {
      const double r0 = edges[a], r1 = edges[a + 1];
      double reflected = 0.0, transmitted = 0.0;
      for (int i = 0; i < rule.size(); ++i) {
        const std::size_t at = a * rule.nodes.size() + static_cast<std::size_t>(i);
        const double w = rule.weights[static_cast<std::size_t>(i)] * (r1 - r0) * 2.0 * kPi * radii[at];
        reflected += w * points.reflectance[at];
        transmitted += w * points.transmittance[at];
      }
      const double area = kPi * (r1 * r1 - r0 * r0);
      // 1e-5 relative, or 1e-7 per mfp^2 (the peaks are near 1 per mfp^2).
      EXPECT_NEAR(reflected / area, annuli.reflectance[a], 1e-5 * annuli.reflectance[a] + 1e-7) << tau << " " << r0;
      EXPECT_NEAR(transmitted / area, annuli.transmittance[a], 1e-5 * annuli.transmittance[a] + 1e-7)
          << tau << " " << r0;
    }
  }
  const double zero[] = {0.0};
  EXPECT_THROW(layer_profile_at({kInf, 0.95, 0.7}, zero, test::profile_test_options()), std::invalid_argument);
}

// Far from the source, where diffusion holds, the exact profile takes the diffusion dipole's shape; near it the dipole
// misses the light scattered a few times. A weakly absorbing half-space (Omega 0.99, g 0.8; the transport mean free
// path is 4.8 mean free paths): within 6% of the dipole from 16 to 48 mean free paths, and 2-4 times above it inside
// one transport mean free path. The dipole's own closed-form total checks its formula.
TEST(LayerProfile, FarFromTheSourceTheShapeIsTheDiffusionDipoles) {
  double dipole_total = 0.0;
  const QuadratureRule rule = gauss_legendre(64, 0.0, 1.0);
  for (int i = 0; i < rule.size(); ++i) {  // r = t / (1 - t) maps [0, 1) onto [0, inf)
    const double t = rule.nodes[static_cast<std::size_t>(i)], r = t / (1.0 - t);
    dipole_total += rule.weights[static_cast<std::size_t>(i)] * 2.0 * kPi * r *
                    diffusion_dipole_reflectance(0.99, 0.8, r) / ((1.0 - t) * (1.0 - t));
  }
  EXPECT_NEAR(dipole_total, diffusion_dipole_total_reflectance(0.99, 0.8), 1e-4 * dipole_total);

  const std::vector<double> radii = {0.5, 1.0, 16.0, 24.0, 32.0, 48.0};
  LayerProfileOptions options = test::profile_test_options();
  options.frequencies = 48;
  const LayerProfile exact = layer_profile_at({kInf, 0.99, 0.8}, radii, options);
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const double ratio = exact.reflectance[i] / diffusion_dipole_reflectance(0.99, 0.8, radii[i]);
    std::printf("  r %5.1f  exact / dipole %.4f\n", radii[i], ratio);
    if (radii[i] >= 16.0) {
      EXPECT_NEAR(ratio, 1.0, 0.06) << radii[i];
    } else {
      EXPECT_GT(ratio, 1.5) << radii[i];
    }
  }
}

// The annuli's powers add up to the light that leaves (the profile's integral is R(0)), and single scattering's
// closed form through all space is its transform at k = 0.
TEST(LayerProfile, PowersAddUpToTheDirectionalAlbedo) {
  std::vector<double> edges = {0.0};
  for (double r = 0.05; r < 120.0; r *= 1.25) edges.push_back(r);
  const LayerProfile profile = layer_profile({kInf, 0.95, 0.6}, edges, test::profile_test_options());
  double power = 0.0;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    power += profile.reflectance[i] * kPi * (edges[i + 1] * edges[i + 1] - edges[i] * edges[i]);
  }
  std::printf("  through r < %.1f: %.7f   R(0): %.7f\n", edges.back(), power, profile.total_reflectance);
  EXPECT_NEAR(power, profile.total_reflectance, 1e-6);
  for (const LayerFace face : {LayerFace::Top, LayerFace::Bottom}) {
    EXPECT_NEAR(single_scattered_power(1.5, 0.8, 0.3, face, 0.0, kInf),
                single_scattered_transform(1.5, 0.8, 0.3, face, 0.0), 1e-9);
  }
  // The closed-form transform of the half-space against the panels' one, at k > 0.
  EXPECT_NEAR(single_scattered_transform(kInf, 0.8, 0.3, LayerFace::Top, 2.0),
              single_scattered_transform(60.0, 0.8, 0.3, LayerFace::Top, 2.0), 1e-7);
  EXPECT_THROW(layer_profile({kInf, 0.95, 0.6}, std::vector<double>{1.0, 0.5}, test::profile_test_options()),
               std::invalid_argument);
  EXPECT_THROW(single_scattered_power(kInf, 0.5, 0.0, LayerFace::Bottom, 0.0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace skinlayer
