// The next-event estimate of the multiply scattered BSDF (core/reference/multiple_scattering_estimate.h), which the
// lobe's table is made of, against the walk's own exits (binned, no next-event estimation): the light that leaves after
// two or more meetings in rings of exit angle, on both sides, for light from above and from inside, within the
// walk's noise and the estimate's. And the estimate is reciprocal where the lobe is: reflection f(i -> o) = f(o -> i),
// and transmission f(above i -> below o) = eta^2 f(below o -> above i), within its noise (5%).
#include "core/reference/multiple_scattering_estimate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/conventions.h"
#include "core/reference/microsurface_walk.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

constexpr int kRings = 6;  // 15 degrees each

TEST(MultipleScatteringEstimate, RingsHoldTheWalksMultiplyScatteredLight) {
  const std::vector<double> azimuths = [] {
    std::vector<double> a;
    for (int k = 0; k <= 72; ++k) a.push_back(k * kPi / 72.0);
    return a;
  }();
  const QuadratureRule in_ring = gauss_legendre(4, 0.0, 1.0);
  for (const auto& [eta, above] : {std::pair{1.4, true}, std::pair{1.4, false}, std::pair{2.0, false}}) {
    const RoughDielectric interface{eta, 0.5, MicrofacetModel::Multiple};
    const double theta_i = 50.0 * kPi / 180.0;
    // The estimate at 4 Gauss polar angles per ring, integrated over the ring and (trapezoid) over azimuth.
    std::vector<double> thetas;
    for (int r = 0; r < kRings; ++r) {
      for (int k = 0; k < in_ring.size(); ++k) {
        thetas.push_back((r + in_ring.nodes[static_cast<std::size_t>(k)]) * kPi / 2.0 / kRings);
      }
    }
    MultipleScatteringEstimateOptions options;
    options.walks_with_meetings = 40'000;
    options.seed = 3;
    const MultipleScatteringEstimate estimate =
        estimate_multiple_scattering(interface, theta_i, above, thetas, azimuths, options);
    // The walk: exits of two or more meetings, by ring.
    const MicrosurfaceWalk walk(interface);
    std::mt19937_64 random(17);
    const Vec3 wi = direction_from_angles(theta_i, 0.0);
    const Vec3 from = above ? wi : Vec3(wi.x(), wi.y(), -wi.z());
    constexpr long kWalks = 1'000'000;
    std::vector<double> rings(2 * kRings, 0.0);
    for (long k = 0; k < kWalks; ++k) {
      const MicrosurfaceExit exit = walk.walk(from, random);
      if (exit.order < 2) continue;
      const int side = exit.direction.z() * from.z() > 0.0 ? 0 : 1;
      const double theta = std::acos(std::min(1.0, std::abs(exit.direction.z())));
      const int ring = std::min(static_cast<int>(theta / (kPi / 2.0) * kRings), kRings - 1);
      rings[static_cast<std::size_t>(side * kRings + ring)] += 1.0 / kWalks;
    }
    for (int side = 0; side < 2; ++side) {
      for (int r = 0; r < kRings; ++r) {
        double share = 0.0;  // int f cos sin dtheta dphi over the ring, both halves of the azimuths
        for (int k = 0; k < in_ring.size(); ++k) {
          const std::size_t t = static_cast<std::size_t>(r * in_ring.size() + k);
          double around = 0.0;
          for (std::size_t j = 0; j < azimuths.size(); ++j) {
            const double weight = (j == 0 || j + 1 == azimuths.size() ? 0.5 : 1.0) * kPi / 72.0;
            around += 2.0 * weight * estimate.at(side, t, j);
          }
          share += in_ring.weights[static_cast<std::size_t>(k)] * (kPi / 2.0 / kRings) * std::cos(thetas[t]) *
                   std::sin(thetas[t]) * around;
        }
        const double walked = rings[static_cast<std::size_t>(side * kRings + r)];
        const double noise = 4.0 * std::sqrt(std::max(walked, 1.0 / kWalks) / kWalks);
        EXPECT_NEAR(share, walked, noise + 0.02 * walked)
            << "eta " << eta << (above ? " from above" : " from inside") << (side ? " beyond" : " back") << " ring "
            << r;
      }
    }
  }
}

TEST(MultipleScatteringEstimate, IsReciprocalWithinItsNoise) {
  const RoughDielectric interface{1.4, 0.5, MicrofacetModel::Multiple};
  const double a = 30.0 * kPi / 180.0, b = 65.0 * kPi / 180.0;
  const std::vector<double> phis = {2.6, 3.0, kPi};  // forward, where the lobe is (its back holds 1e-5 of it)
  MultipleScatteringEstimateOptions options;
  options.walks_with_meetings = 40'000;
  const auto from = [&](double theta, bool above, double to) {
    const double exits[] = {to};
    return estimate_multiple_scattering(interface, theta, above, exits, phis, options);
  };
  const MultipleScatteringEstimate above_a = from(a, true, b), above_b = from(b, true, a);
  const MultipleScatteringEstimate below_a = from(a, false, b), below_b = from(b, false, a);
  for (std::size_t j = 0; j < phis.size(); ++j) {
    EXPECT_NEAR(above_a.at(0, 0, j), above_b.at(0, 0, j), 0.05 * above_a.at(0, 0, j) + 1e-6) << j;
    EXPECT_NEAR(below_a.at(0, 0, j), below_b.at(0, 0, j), 0.05 * below_a.at(0, 0, j) + 1e-6) << j;
    EXPECT_NEAR(above_a.at(1, 0, j), 1.4 * 1.4 * below_b.at(1, 0, j), 0.05 * above_a.at(1, 0, j) + 1e-6) << j;
  }
}

}  // namespace
}  // namespace skinlayer
