// The transmittance profile of finite layers and stacks lit through any top (docs/model.md §21.15): the continuous
// low orders against the open slab's closed form and the ordinates' own, the unscattered light against 2 E3, and the
// whole profile against the walk and MCML's published sample.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/conventions.h"
#include "core/material.h"
#include "core/series/quadrature.h"
#include "core/spatial/entering_radiance.h"
#include "core/spatial/lateral_frequency_response.h"
#include "core/spatial/lateral_top_interface.h"
#include "core/spatial/layer_profile.h"
#include "core/spatial/rough_top_single_scattering.h"
#include "core/spatial/single_scattering_profile.h"
#include "core/spatial/transmitted_low_orders.h"
#include "tests/core/reference_csv.h"
#include "tests/core/spatial/profile_against_walk.h"
#include "tests/core/spatial/rough_top_layers.h"

namespace skinlayer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The collimated beam into one open slab, through the general paths (entering along any direction, scattered at any
// depth of any slab): the open slab's own closed form (single_scattering_profile.h), in annuli and at points.
TEST(FiniteStackTransmittance, CollimatedBeamGivesTheOpenSlabsClosedForm) {
  const EnteringRadiance beam(open_top_interface(12, 4, Incidence::Normal), std::nullopt, 12);
  for (const double tau : {0.5, 2.0}) {
    const LateralSlab slab{tau, 0.9, 0.8, 1.0};
    for (const auto& [r0, r1] : {std::pair{0.0, 0.1}, {0.1, 0.5}, {0.5, 1.0}, {1.0, 3.0}, {0.0, kInf}}) {
      const double closed = single_scattered_power(tau, 0.9, 0.8, LayerFace::Bottom, r0, r1);
      EXPECT_NEAR(single_scattered_transmitted_power({&slab, 1}, beam, {}, r0, r1), closed, 1e-7 * closed)
          << tau << " [" << r0 << ", " << r1 << ")";
    }
    for (const double r : {0.01, 0.3, 1.0, 4.0}) {
      const double closed = single_scattered_density(tau, 0.9, 0.8, LayerFace::Bottom, r);
      EXPECT_NEAR(single_scattered_transmitted_density({&slab, 1}, beam, {}, r), closed, 1e-7 * closed) << r;
    }
  }
}

// Diffuse light through no interface: the unscattered light leaving a slab is 2 E3(tau) in all, here by a fine
// midpoint sum over mu, and its density integrates to its annulus power.
TEST(FiniteStackTransmittance, DiffuseUnscatteredLightIsTwoE3) {
  const EnteringRadiance diffuse(open_top_interface(12, 4, Incidence::Diffuse), std::nullopt, 12);
  EXPECT_EQ(diffuse.collimated(), 0.0);
  const LateralSlab slabs[] = {{0.4, 0.9, 0.8, 1.0}, {0.6, 0.5, 0.0, 0.5}};  // tau 1, geometric depth 1.6
  double two_e3 = 0.0;
  constexpr int kSteps = 200000;
  for (int i = 0; i < kSteps; ++i) {
    const double mu = (i + 0.5) / kSteps;
    two_e3 += 2.0 * mu * std::exp(-1.0 / mu) / kSteps;
  }
  EXPECT_NEAR(unscattered_transmitted_power(slabs, diffuse, {}, 0.0, 1e9), two_e3, 1e-7);
  const double r0 = 0.5, r1 = 2.0;
  double integral = 0.0;
  const QuadratureRule rule = gauss_legendre(32, r0, r1);
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    integral += rule.weights[i] * 2.0 * kPi * rule.nodes[i] *
                unscattered_transmitted_density(slabs, diffuse, {}, rule.nodes[i]);
  }
  const double power = unscattered_transmitted_power(slabs, diffuse, {}, r0, r1);
  EXPECT_NEAR(integral, power, 1e-8 * power);
  // 2 pi r times the density is that of r = 1.6 tan(theta) under radiance 1/pi: 2 mu e^{-1/mu} |d mu / dr|.
  const double r = 1.0, mu = 1.6 / std::hypot(1.6, r);
  EXPECT_NEAR(2.0 * kPi * r * unscattered_transmitted_density(slabs, diffuse, {}, r),
              2.0 * mu * std::exp(-1.0 / mu) * 1.6 * r / std::pow(1.6 * 1.6 + r * r, 1.5), 1e-12);
}

// The entering radiance holds the light the nodes hold: its directions carry, in all, the node radiance's flux.
TEST(FiniteStackTransmittance, EnteringRadianceCarriesTheNodesFlux) {
  for (const MicrofacetModel model : {MicrofacetModel::Single, MicrofacetModel::Multiple}) {
    for (const double sigma : {0.1, 0.3, 0.8}) {
      const RoughDielectric rough{1.4, sigma, model};
      const LateralTopInterface top = lateral_top_interface(rough, 12, 4);
      const EnteringRadiance entering(top, rough, 12);
      const QuadratureRule q = double_gauss_half_range(12);
      double nodes = 0.0, continuous = 0.0;
      for (int j = 0; j < 12; ++j) nodes += 2.0 * kPi * q.weights[j] * q.nodes[j] * top.source(j);
      for (const double power : entering.directions().weights) continuous += power;
      EXPECT_NEAR(continuous, nodes, 1e-5) << sigma;
    }
  }
}

// In k-space, the node radiance's low orders on the bottom are the ordinates' own: with nothing scattering, the
// solve's transmittance is the unscattered part; with a small albedo and a top that sends nothing back, what it adds
// is the first order.
TEST(FiniteStackTransmittance, LowOrdersInKSpaceAreTheOrdinatesOwn) {
  const LateralFrequencyResolution resolution{8, 10};
  const LateralTopInterface top = lateral_top_interface(RoughDielectric{1.4, 0.4}, 8, 10);
  LateralTopInterface letting_out = top;
  for (Eigen::MatrixXd& mode : letting_out.reflection) mode.setZero();
  for (const double k : {0.0, 0.7, 3.0}) {
    constexpr double kSmall = 1e-6;
    const LateralSlab clear[] = {{0.8, 0.0, 0.7, 1.0}, {1.5, 0.0, 0.3, 0.5}};
    const LateralSlab faint[] = {{0.8, kSmall, 0.7, 1.0}, {1.5, kSmall, 0.3, 0.5}};
    const RoughTopLowOrders orders = rough_top_low_orders(faint, top, k, resolution);
    const double unscattered = lateral_stack_response(clear, &top, k, resolution).transmittance;
    EXPECT_NEAR(orders.transmitted_unscattered, unscattered, 1e-12) << k;
    const double once = lateral_stack_response(faint, &letting_out, k, resolution).transmittance - unscattered;
    EXPECT_NEAR(orders.transmitted_once, once, 1e-5 * std::abs(once)) << k;
  }
}

using test::rough_top_layer;

// The walk checks below take 24 nodes (test::transmitted_radiance_options): the refracted lobe enters on the nodes
// nearest the normal, and each node's stream through the slab makes a ring that the multiply scattered light keeps. At
// 12, 16, 20 and 24 nodes the worst annulus below is 4.7%, 2.4%, 1.7% and 1.0% off the walk (sigma 0.3); the command
// computes such transmittance on 24.
const std::vector<double> kSlabEdges = {0.0, 0.025, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3, 0.4,
                                        0.6, 0.8,   1.0,  1.5,   2.0, 3.0,  4.0, 6.0, 8.0};

// A finite slab under a rough top: both faces against the walk, which refracts the beam facet by facet and records
// where each photon leaves, the unscattered ones included.
TEST(FiniteStackTransmittance, RoughTopOverAFiniteSlabMatchesTheWalk) {
  const Material m = rough_top_layer(1.0, 0.3, 0.9, 0.8);
  test::expect_profile_matches_the_walk(profile_layer(m), m, test::transmitted_radiance_options(), kSlabEdges);
}

// A rougher top, whose lobe spreads over more nodes, over a more absorbing slab.
TEST(FiniteStackTransmittance, RougherTopOverAnAbsorbingSlabMatchesTheWalk) {
  const Material m = rough_top_layer(1.5, 0.8, 0.8, 0.6);
  test::expect_profile_matches_the_walk(profile_layer(m), m, test::transmitted_radiance_options(), kSlabEdges);
}

// A finite two-layer stack in millimetres under a rough top: 0.05 mm at mu_t 20/mm over 0.025 mm at 40/mm, under
// Stam's single-scattering interfaces. Under the default ones every annulus agrees too (within 1.1% beyond 0.2 mm,
// where the azimuth-uniform lobe of issue 53 left it 4% low) but the central one, 0-2.5 um: the profile gives the
// same value there under both models, 2.7% (4.3 SE) under the default's walk and 1.8% (2.8 SE) under this one's,
// whose walks differ by one of their standard errors.
TEST(FiniteStackTransmittance, TwoLayerStackInMillimetresMatchesTheWalk) {
  Material m = rough_top_layer(1.0, 0.35, 0.9, 0.8);
  m.microfacet = MicrofacetModel::Single;
  m.extinction = 20.0;
  m.below = {StackedLayer{1.0, 0.95, 0.5, std::nullopt, 40.0}};
  test::expect_profile_matches_the_walk(profile_layer(m), m, test::transmitted_radiance_options(),
                                        {0.0, 0.0025, 0.005, 0.01, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2, 0.3, 0.4},
                                        20.0);
}

}  // namespace
}  // namespace skinlayer
