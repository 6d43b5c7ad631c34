// One rough interface alone, direction by direction, through the whole solver: a material with no medium (T 1)
// over an index-matched half-space is the top interface seen from above, and that material upside down
// (core/solve/upside_down.h) is the same interface seen from inside; at sigma 0.3, 0.5 and 1, eta 1.2, 1.4 and 2 and
// theta_i 0, 30, 60 and 80 degrees.
//  - Against the microsurface random walk (core/reference/microsurface_walk.h): its BRDF (the specular lobe and the
//    multiply scattered light the tables carry) and its BTDF (the unscattered lobe and the multiply scattered light
//    through it), integrated over bins 10 degrees in theta_o by 30 degrees in phi, hold the same share of the light as
//    the walk's exits in them, within 4 of the walk's standard errors or 2% of the bin, in every bin that holds 0.1%
//    of the light or more. Azimuths are folded onto [0, 180] degrees (the BSDF is even in phi), so each bin is a pair
//    of mirror bins.
//  - Against the solver's own directional albedos: the BSDF that `eval` returns, integrated over both hemispheres,
//    is the reflectance and the transmittance within 0.1% of the light.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/conventions.h"
#include "core/material.h"
#include "core/reference/bin_average.h"
#include "core/reference/microsurface_walk.h"
#include "core/solve/upside_down.h"
#include "core/series/quadrature.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

constexpr int kThetaBins = 9;  // 10 degrees
constexpr int kPhiBins = 6;    // 30 degrees on [0, 180]
constexpr double kFloor = 1e-3;

// The material that is the interface alone, seen from above or from inside.
Material interface_alone(double sigma, double eta, bool from_above) {
  Material above;
  above.sigma = sigma;
  above.eta = eta;
  above.tau = 0.0;  // T = 1: no medium
  above.albedo = 0.0;
  above.bottom.kind = BottomKind::Matched;
  return from_above ? above : *upside_down(above);
}

struct Worst {
  double sigmas = 0.0;    // |difference| / standard error, in the bins that fail 2%
  double relative = 0.0;  // |difference| / walk, in the bins that fail 4 SE
  int bins = 0, failed = 0;
};

// The walk's share of the light in each (side, theta, phi) bin, light from above (or from below) at theta_i.
std::vector<double> walk_shares(const RoughDielectric& interface, double theta_i, bool from_above, long walks,
                                std::uint64_t seed) {
  const MicrosurfaceWalk walk(interface);
  std::mt19937_64 random(seed);
  Vec3 wi = direction_from_angles(theta_i, 0.0);
  if (!from_above) wi.z() = -wi.z();
  std::vector<double> shares(2 * kThetaBins * kPhiBins, 0.0);
  for (long k = 0; k < walks; ++k) {
    const Vec3 d = walk.walk(wi, random).direction;
    const int side = d.z() * wi.z() > 0.0 ? 0 : 1;
    const double theta = std::acos(std::min(1.0, std::abs(d.z())));
    const double phi = std::abs(std::atan2(d.y(), d.x()));
    const int t = std::min(static_cast<int>(theta / (kPi / 2.0) * kThetaBins), kThetaBins - 1);
    const int p = std::min(static_cast<int>(phi / kPi * kPhiBins), kPhiBins - 1);
    shares[static_cast<std::size_t>((side * kThetaBins + t) * kPhiBins + p)] += 1.0 / static_cast<double>(walks);
  }
  return shares;
}

Worst compare(double sigma, double eta, double theta_deg, bool from_above, long walks, std::uint64_t seed) {
  const Material material = interface_alone(sigma, eta, from_above);
  const LayerTables tables = solve(material);
  const double theta_i = theta_deg * kPi / 180.0;
  const std::vector<double> walk =
      walk_shares({eta, sigma, MicrofacetModel::Multiple}, theta_i, from_above, walks, seed);
  Worst worst;
  for (int side = 0; side < 2; ++side) {
    for (int t = 0; t < kThetaBins; ++t) {
      for (int p = 0; p < kPhiBins; ++p) {
        const AngularBin bin{side == 0 ? ExitSide::Reflected : ExitSide::Transmitted, t * kPi / 2.0 / kThetaBins,
                             (t + 1) * kPi / 2.0 / kThetaBins, p * kPi / kPhiBins, (p + 1) * kPi / kPhiBins};
        const double solver =
            2.0 * layer_bsdf_bin_average(material, tables, theta_i, bin) * bin.projected_solid_angle();
        const double share = walk[static_cast<std::size_t>((side * kThetaBins + t) * kPhiBins + p)];
        if (std::max(share, solver) < kFloor) continue;
        ++worst.bins;
        const double error = std::sqrt(std::max(share, 1.0 / static_cast<double>(walks)) / static_cast<double>(walks));
        const double difference = std::abs(solver - share);
        const bool within_noise = difference <= 4.0 * error;
        const bool within_share = difference <= 0.02 * share;
        if (!within_noise && !within_share) {
          ++worst.failed;
          ADD_FAILURE() << "sigma " << sigma << " eta " << eta << (from_above ? " from above" : " from inside")
                        << " theta_i " << theta_deg << ": " << (side == 0 ? "reflected" : "transmitted") << " theta_o ["
                        << 10 * t << ", " << 10 * (t + 1) << ") phi [" << 30 * p << ", " << 30 * (p + 1) << "): walk "
                        << share << " +- " << error << ", solver " << solver;
        }
        if (!within_share) worst.sigmas = std::max(worst.sigmas, difference / error);
        if (!within_noise) worst.relative = std::max(worst.relative, difference / share);
      }
    }
  }
  return worst;
}

TEST(InterfaceDirections, EveryBinHoldsTheWalksShareOfTheLight) {
  std::uint64_t seed = 1;
  Worst all;
  for (const double sigma : {0.3, 0.5, 1.0}) {
    for (const double eta : {1.2, 1.4, 2.0}) {
      for (const bool from_above : {true, false}) {
        for (const double theta : {0.0, 30.0, 60.0, 80.0}) {
          const Worst w = compare(sigma, eta, theta, from_above, 400'000, seed++);
          std::printf(
              "sigma %.1f eta %.1f %s theta_i %2.0f: %3d bins, %d outside; worst %.2f SE beyond 2%%, %.2f%% beyond 4 "
              "SE\n",
              sigma, eta, from_above ? "above " : "inside", theta, w.bins, w.failed, w.sigmas, 100.0 * w.relative);
          all.bins += w.bins;
          all.failed += w.failed;
        }
      }
    }
  }
  std::printf("%d bins judged, %d outside 4 SE and 2%%\n", all.bins, all.failed);
}

// The hemisphere integral of a BSDF times |cos theta_o|, on 1-degree panels in theta_o and in phi (within 30
// degrees of the forward plane, where the lobes are sharp; 10 degrees elsewhere), 4-point Gauss-Legendre on each.
template <typename F>
double hemisphere_integral(F bsdf) {
  const QuadratureRule unit = gauss_legendre(4, 0.0, 1.0);
  std::vector<std::pair<double, double>> phis;  // node, weight on [0, pi], doubled for the mirror half
  for (double lo = 0.0; lo < 180.0;) {
    const double hi = lo + (lo >= 150.0 ? 1.0 : 10.0);
    for (int k = 0; k < unit.size(); ++k) {
      phis.emplace_back((lo + (hi - lo) * unit.nodes[static_cast<std::size_t>(k)]) * kPi / 180.0,
                        2.0 * (hi - lo) * kPi / 180.0 * unit.weights[static_cast<std::size_t>(k)]);
    }
    lo = hi;
  }
  double sum = 0.0;
  for (int panel = 0; panel < 90; ++panel) {
    for (int k = 0; k < unit.size(); ++k) {
      const double theta = (panel + unit.nodes[static_cast<std::size_t>(k)]) * kPi / 180.0;
      const double measure = std::cos(theta) * std::sin(theta) * kPi / 180.0 * unit.weights[static_cast<std::size_t>(k)];
      for (const auto& [phi, weight] : phis) sum += measure * weight * bsdf(theta, phi);
    }
  }
  return sum;
}

TEST(InterfaceDirections, EvalIntegratesToTheAlbedos) {
  double worst = 0.0;
  for (const double sigma : {0.3, 0.5, 1.0}) {
    for (const double eta : {1.2, 1.4, 2.0}) {
      for (const bool from_above : {true, false}) {
        const Material material = interface_alone(sigma, eta, from_above);
        const LayerTables tables = solve(material);
        for (const double theta : {0.0, 30.0, 60.0, 80.0}) {
          const double theta_i = theta * kPi / 180.0;
          const double angles[] = {theta_i};
          const DirectionalAlbedo albedo = directional_albedo(material, angles).front();
          const double reflected = hemisphere_integral([&](double theta_o, double phi) {
            return brdf_surface(material, theta_i, theta_o, phi) + tables.brdf_subsurface(theta_i, theta_o, phi);
          });
          const double transmitted =
              hemisphere_integral([&](double theta_o, double phi) { return tables.btdf(theta_i, theta_o, phi); });
          const std::string where = "sigma " + std::to_string(sigma) + " eta " + std::to_string(eta) +
                                    (from_above ? " from above" : " from inside") + " theta_i " + std::to_string(theta);
          EXPECT_NEAR(reflected, albedo.reflectance(), 1e-3) << where;
          EXPECT_NEAR(transmitted, albedo.transmittance, 1e-3) << where;
          worst = std::max({worst, std::abs(reflected - albedo.reflectance()),
                            std::abs(transmitted - albedo.transmittance)});
        }
      }
    }
  }
  std::printf("eval integrated against the albedos: worst difference %.2e of the light\n", worst);
}

}  // namespace
}  // namespace skinlayer
