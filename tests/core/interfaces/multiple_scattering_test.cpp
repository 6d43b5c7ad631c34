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
#include <utility>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/interface_albedo.h"
#include "core/interfaces/multiple_scattering_table.h"
#include "core/reference/microsurface_walk.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

RoughDielectric multiple(double eta, double sigma) { return {eta, sigma, MicrofacetModel::Multiple}; }

TEST(MultipleScattering, TheLobeIsReciprocalModeByModeAndAbsentWithoutAnInterface) {
  for (const RoughDielectric interface :
       {multiple(1.4, 0.5), multiple(2.2, 1.0), multiple(1.1, 0.2), multiple(0.7, 0.3)}) {
    const MultipleScatteringLobe lobe(interface, 16);
    ASSERT_EQ(lobe.modes(), 16);
    for (const int m : {0, 1, 5, 15}) {
      for (const double a : {0.05, 0.3, 0.7, 1.0}) {
        for (const double b : {0.1, 0.5, 0.95}) {
          for (const bool above : {true, false}) {
            EXPECT_DOUBLE_EQ(lobe.reflection(above, m, a, b), lobe.reflection(above, m, b, a));
            if (m == 0) {
              EXPECT_GE(lobe.reflection(above, m, a, b), 0.0);
            }
          }
          EXPECT_NEAR(lobe.transmission(true, m, a, b),
                      interface.eta * interface.eta * lobe.transmission(false, m, b, a),
                      1e-15 * (1.0 + std::abs(lobe.transmission(true, m, a, b))));
        }
      }
    }
    // The lobe itself: reciprocal, and not negative.
    for (const double phi : {0.0, 2.0, 3.1}) {
      EXPECT_NEAR(lobe.reflection_at(false, 0.3, 0.8, phi), lobe.reflection_at(false, 0.8, 0.3, phi), 1e-15);
      EXPECT_NEAR(lobe.transmission_at(true, 0.3, 0.8, phi),
                  interface.eta * interface.eta * lobe.transmission_at(false, 0.8, 0.3, phi), 1e-14);
    }
    EXPECT_EQ(lobe.reflection(true, 16, 0.5, 0.5), 0.0);  // beyond the modes it holds
  }
  const MultipleScatteringLobe none(multiple(1.0, 0.5), 16);
  EXPECT_EQ(none.modes(), 0);
  EXPECT_EQ(none.reflection(true, 0, 0.5, 0.5), 0.0);
  EXPECT_EQ(none.transmission(false, 0, 0.5, 0.5), 0.0);
  EXPECT_EQ(none.reflection_at(true, 0.5, 0.5, 3.0), 0.0);
}

// An interface of eta < 1 is the interface of 1/eta upside down: its reflections swap and its transmissions swap
// sides.
TEST(MultipleScattering, AnInterfaceUpsideDownIsTheSameLobe) {
  const MultipleScatteringLobe up(multiple(1.4, 0.4), 8), down(multiple(1.0 / 1.4, 0.4), 8);
  for (const int m : {0, 3}) {
    for (const double a : {0.2, 0.6, 0.95}) {
      for (const double b : {0.15, 0.5, 0.9}) {
        EXPECT_NEAR(up.reflection(true, m, a, b), down.reflection(false, m, a, b), 1e-14);
        EXPECT_NEAR(up.reflection(false, m, a, b), down.reflection(true, m, a, b), 1e-14);
        EXPECT_NEAR(up.transmission(true, m, a, b), down.transmission(false, m, a, b), 1e-14);
        EXPECT_NEAR(up.transmission(false, m, a, b), down.transmission(true, m, a, b), 1e-14);
      }
    }
  }
}

// The modes are the exact cosine series of the lobe (linear in azimuth between its samples), where it is sharp
// (grazing, forward) too: each mode against the lobe's own cosine integral, by a fine trapezoid rule, within 1e-6
// of its peak and in absolute terms (mode 0 is held at 0 or above where the polar interpolation dips below).
TEST(MultipleScattering, TheModesAreTheLobesCosineSeries) {
  const MultipleScatteringLobe lobe(multiple(1.4, 0.3), 64);
  constexpr int kSteps = 36000;  // 0.005 degrees
  for (const auto& [mu_i, mu_o] : {std::pair{0.5, 0.5}, std::pair{0.17, 0.17}, std::pair{0.9, 0.3}}) {
    for (const bool above : {true, false}) {
      for (const int m : {0, 1, 7, 40, 63}) {
        double r = 0.0, t = 0.0;
        for (int k = 0; k <= kSteps; ++k) {
          const double phi = kPi * k / kSteps, weight = (k == 0 || k == kSteps ? 0.5 : 1.0) * kPi / kSteps;
          const double c = (m == 0 ? 1.0 : 2.0) / kPi * std::cos(m * phi) * weight;
          r += c * lobe.reflection_at(above, mu_i, mu_o, phi);
          t += c * lobe.transmission_at(above, mu_i, mu_o, phi);
        }
        const double r_peak = std::abs(lobe.reflection_at(above, mu_i, mu_o, kPi));
        const double t_peak = std::abs(lobe.transmission_at(above, mu_i, mu_o, kPi));
        EXPECT_NEAR(lobe.reflection(above, m, mu_i, mu_o), r, 1e-6 * (r_peak + 1.0))
            << mu_i << " " << mu_o << " " << above << " m " << m;
        EXPECT_NEAR(lobe.transmission(above, m, mu_i, mu_o), t, 1e-6 * (t_peak + 1.0))
            << mu_i << " " << mu_o << " " << above << " m " << m;
      }
    }
  }
}

// At the grid's polar angles the lobe carries, from either side, exactly the light single scattering loses there (the
// loss table's, interpolated as the shapes are), split between reflection and transmission; between the table's
// nodes in sigma and E too.
TEST(MultipleScattering, TheLobeCarriesTheLossAtItsGridAngles) {
  for (const RoughDielectric interface : {multiple(1.4, 0.5), multiple(1.33, 0.45), multiple(2.0, 0.7),
                                          multiple(1.0 / 1.3, 0.25)}) {
    const MultipleScatteringLobe lobe(interface, 4);
    const bool flipped = interface.eta < 1.0;
    const MultipleScatteringShape shape =
        multiple_scattering_shape(interface.sigma, flipped ? 1.0 / interface.eta : interface.eta);
    for (int k = 0; k + 1 < MultipleScatteringSamples::kAngles; ++k) {
      const double mu = std::cos(degrees_to_radians(MultipleScatteringSamples::kAngleStep * k));
      for (const bool above : {true, false}) {
        const double loss = (above != flipped ? shape.loss_above : shape.loss_below)[static_cast<std::size_t>(k)];
        const double carried = lobe.energy(above, true, mu) + lobe.energy(above, false, mu);
        EXPECT_NEAR(carried, loss, 1e-9 + 1e-9 * loss) << interface.sigma << " " << interface.eta << " " << k;
      }
    }
  }
}

// Continuous in sigma and eta across the table's nodes (sigma 0.3, E 1.4) and between them.
TEST(MultipleScattering, TheLobeIsContinuousInSigmaAndEta) {
  const auto value = [](double sigma, double eta) {
    const MultipleScatteringLobe lobe(multiple(eta, sigma), 1);
    return lobe.reflection_at(false, 0.3, 0.4, 3.0) + lobe.transmission_at(true, 0.5, 0.8, 2.5);
  };
  for (const auto& [sigma, eta] : {std::pair{0.3, 1.4}, std::pair{0.35, 1.37}}) {
    const double at = value(sigma, eta);
    for (const double step : {1e-7, -1e-7}) {
      EXPECT_NEAR(value(sigma + step, eta), at, 1e-4 * at) << sigma << " " << eta;
      EXPECT_NEAR(value(sigma, eta + step), at, 1e-4 * at) << sigma << " " << eta;
    }
  }
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
  const MultipleScatteringLobe lobe(interface, 1);
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
        sum += kPi * u.weights[k] *
               (side == 0 ? lobe.reflection(above, 0, mu, mu_o) : lobe.transmission(above, 0, mu, mu_o));
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
