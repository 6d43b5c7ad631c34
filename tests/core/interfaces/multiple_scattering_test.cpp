// The multiply scattered light of a rough interface (core/interfaces/multiple_scattering.h) and the albedos of
// MicrofacetModel::Multiple (core/interfaces/interface_albedo.h):
//  - the lobe is reciprocal (reflection symmetric, transmission with eta^2) and zero without an interface;
//  - the Multiple albedos keep all light, R + T = 1, from both sides at every angle;
//  - against the microsurface random walk (core/reference/microsurface_walk.h), an independent reference: the
//    directional reflectance and transmittance within 0.01 (absolute), and what leaves, in bins of exit angle on
//    either side, within 2% of the directional albedo (R + T = 1) in every bin, and within 2% of the side's own
//    albedo where that side carries 5% of the light or more, beyond the walk's own Monte Carlo error (4 standard
//    errors). The single-scattering part is the walk's
//    own (core/reference's tests), so the bins compare the multiply scattered part: the walk's walks of two or more
//    meetings against the lobe, carrying the exact loss l of single scattering, split by its share.
#include "core/interfaces/multiple_scattering.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/interface_albedo.h"
#include "core/reference/microsurface_walk.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

RoughDielectric multiple(double eta, double sigma) { return {eta, sigma, MicrofacetModel::Multiple}; }

TEST(MultipleScattering, TheLobeIsReciprocalAndAbsentWithoutAnInterface) {
  for (const RoughDielectric interface : {multiple(1.4, 0.5), multiple(2.2, 1.0), multiple(1.1, 0.2)}) {
    const MultipleScatteringLobe lobe(interface);
    for (const double a : {0.05, 0.3, 0.7, 1.0}) {
      for (const double b : {0.1, 0.5, 0.95}) {
        for (const bool above : {true, false}) {
          EXPECT_DOUBLE_EQ(lobe.reflection(above, a, b), lobe.reflection(above, b, a));
          EXPECT_GE(lobe.reflection(above, a, b), 0.0);
        }
        EXPECT_NEAR(lobe.transmission(true, a, b), interface.eta * interface.eta * lobe.transmission(false, b, a),
                    1e-15 * (1.0 + lobe.transmission(true, a, b)));
      }
    }
  }
  const MultipleScatteringLobe none(multiple(1.0, 0.5));
  EXPECT_EQ(none.reflection(true, 0.5, 0.5), 0.0);
  EXPECT_EQ(none.transmission(false, 0.5, 0.5), 0.0);
}

TEST(MultipleScattering, TheMultipleAlbedosKeepAllLight) {
  for (const double sigma : {0.05, 0.3, 1.0}) {
    for (const double eta : {1.05, 1.4, 2.5}) {
      for (const double side : {1.0, -1.0}) {
        for (const double theta : {0.0, 30.0, 60.0, 80.0, 89.0}) {
          const Vec3 wi = side * direction_from_angles(theta * kPi / 180.0, 0.2);
          const InterfaceAlbedo albedo = interface_albedo(multiple(eta, sigma), wi);
          EXPECT_NEAR(albedo.reflectance + albedo.transmittance, 1.0, 1e-12)
              << "sigma " << sigma << " eta " << eta << " side " << side << " theta " << theta;
          EXPECT_GE(albedo.reflectance, 0.0);
          EXPECT_GE(albedo.transmittance, 0.0);
        }
      }
    }
  }
}

constexpr int kPolarBins = 9;  // equal in mu^2 on each side

struct WalkTally {
  double reflected = 0.0;                                    // every order
  std::array<std::array<double, kPolarBins>, 2> multiple{};  // [same side, beyond][bin], two or more meetings
  std::array<double, 2> side_albedo{};
};

WalkTally walk_tally(const RoughDielectric& interface, const Vec3& wi, long walks, std::uint64_t seed) {
  const MicrosurfaceWalk walk(interface);
  std::mt19937_64 random(seed);
  const double each = 1.0 / static_cast<double>(walks);
  WalkTally tally;
  for (long k = 0; k < walks; ++k) {
    const MicrosurfaceExit exit = walk.walk(wi, random);
    const int side = exit.direction.z() * wi.z() > 0.0 ? 0 : 1;
    tally.side_albedo[static_cast<std::size_t>(side)] += each;
    if (side == 0) tally.reflected += each;
    if (exit.order < 2) continue;
    const double mu = std::abs(exit.direction.z());
    const int bin = std::min(static_cast<int>(mu * mu * kPolarBins), kPolarBins - 1);
    tally.multiple[static_cast<std::size_t>(side)][static_cast<std::size_t>(bin)] += each;
  }
  return tally;
}

// The model's multiply scattered energy in each exit bin: l (1 - s) or l s, spread as the lobe over mu_o.
std::array<std::array<double, kPolarBins>, 2> model_bins(const RoughDielectric& interface, const Vec3& wi) {
  const MultipleScatteringLobe lobe(interface);
  const bool above = wi.z() > 0.0;
  const double mu = std::abs(wi.z());
  const double rest = single_scattering_albedo(interface, wi).loss();
  const double share = lobe.transmitted_share(above, mu);
  std::array<std::array<double, kPolarBins>, 2> bins{};
  std::array<double, 2> totals{};
  const QuadratureRule u = gauss_legendre(8, 0.0, 1.0 / kPolarBins);
  for (int side = 0; side < 2; ++side) {
    for (int b = 0; b < kPolarBins; ++b) {
      double sum = 0.0;  // pi int f du over the bin, u = mu_o^2
      for (int k = 0; k < u.size(); ++k) {
        const double mu_o = std::sqrt(u.nodes[k] + static_cast<double>(b) / kPolarBins);
        sum += kPi * u.weights[k] * (side == 0 ? lobe.reflection(above, mu, mu_o) : lobe.transmission(above, mu, mu_o));
      }
      bins[static_cast<std::size_t>(side)][static_cast<std::size_t>(b)] = sum;
      totals[static_cast<std::size_t>(side)] += sum;
    }
  }
  for (int side = 0; side < 2; ++side) {
    const double energy = rest * (side == 0 ? 1.0 - share : share);
    for (double& bin : bins[static_cast<std::size_t>(side)]) {
      bin = totals[static_cast<std::size_t>(side)] > 0.0 ? bin * energy / totals[static_cast<std::size_t>(side)] : 0.0;
    }
  }
  return bins;
}

TEST(MultipleScattering, TheModelIsTheRandomWalkWithinAHundredthAndItsDistributionWithinTwoPercent) {
  constexpr long kWalks = 100000;
  double worst_albedo = 0.0, worst_bin = 0.0;
  std::uint64_t seed = 1;
  for (const double sigma : {0.1, 0.5, 1.0}) {
    for (const double eta : {1.2, 2.0}) {
      const RoughDielectric interface = multiple(eta, sigma);
      for (const double side : {1.0, -1.0}) {
        for (const double theta : {0.0, 60.0, 85.0}) {
          const std::string where = "sigma " + std::to_string(sigma) + " eta " + std::to_string(eta) + " side " +
                                    std::to_string(side) + " theta " + std::to_string(theta);
          const Vec3 wi = side * direction_from_angles(theta * kPi / 180.0, 0.0);
          const WalkTally walk = walk_tally(interface, wi, kWalks, seed++);
          const InterfaceAlbedo model = interface_albedo(interface, wi);
          EXPECT_NEAR(model.reflectance, walk.reflected, 0.01) << where;
          worst_albedo = std::max(worst_albedo, std::abs(model.reflectance - walk.reflected));
          const auto bins = model_bins(interface, wi);
          for (std::size_t s = 0; s < 2; ++s) {
            for (std::size_t b = 0; b < kPolarBins; ++b) {
              const double difference = std::abs(bins[s][b] - walk.multiple[s][b]);
              // The walk's error, 4 standard errors (of at least one walk in the bin).
              const double noise = 4.0 * std::sqrt(std::max(walk.multiple[s][b], 1.0 / kWalks) / kWalks);
              // 2% of the directional albedo (R + T = 1), and of the side's own albedo where it holds 5% or more.
              const double albedo = walk.side_albedo[s] >= 0.05 ? walk.side_albedo[s] : 1.0;
              EXPECT_LE(difference, 0.02 * albedo + noise)
                  << where << (s == 0 ? ", back" : ", beyond") << ", bin " << b;
              if (walk.side_albedo[s] >= 0.05) worst_bin = std::max(worst_bin, difference / walk.side_albedo[s]);
            }
          }
        }
      }
    }
  }
  std::printf(
      "[ multiple] against the walk: worst |R - R_walk| %.4f, worst bin %.2f%% of its side's albedo (sides of "
      "5%% or more)\n",
      worst_albedo, 100.0 * worst_bin);
}

}  // namespace
}  // namespace skinlayer
