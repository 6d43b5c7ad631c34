// The azimuth sweep (core/interfaces/interface_azimuth_sweep.h) rewrites the rough dielectric BSDF in the pair's
// polar quantities and cos/sin of the azimuth: it must give microfacet.h's rough_dielectric_bsdf, the reference,
// to round-off, on the directions the interface operators use (double-Gauss nodes both ways, grazing columns, the
// projector's azimuths) and at random pairs, for reflection and transmission on both sides.
#include "core/interfaces/interface_azimuth_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/series/fourier.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

struct Worst {
  double peak = 0.0, error = 0.0;
};

void compare(const RoughDielectric& interface, double mu_from, double mu_to, double cos_phi, double sin_phi,
             Worst& worst) {
  const Vec3 wi = -propagation_direction(mu_from, 0.0);
  const double g1_wi = smith_g1_beckmann(wi.z(), interface.sigma);
  const double g1_wo = smith_g1_beckmann(mu_to, interface.sigma);
  const double sin_to = std::sqrt(std::max(0.0, 1.0 - mu_to * mu_to));
  const Vec3 wo(sin_to * cos_phi, sin_to * sin_phi, mu_to);
  const double reference = rough_dielectric_bsdf(interface, wi, wo, g1_wi, g1_wo);
  const double swept = InterfaceAzimuthSweep(interface, wi, mu_to, g1_wi, g1_wo).at_azimuth(cos_phi, sin_phi);
  worst.peak = std::max(worst.peak, std::abs(reference));
  worst.error = std::max(worst.error, std::abs(swept - reference));
}

const RoughDielectric kInterfaces[] = {{1.4, 0.05}, {1.05, 0.1}, {1.0 / 1.4, 0.2}, {2.0, 1.0}, {1.0, 0.5}};

TEST(InterfaceAzimuthSweep, EqualsTheMicrofacetBsdfOnTheOperatorsDirections) {
  const QuadratureRule rule = double_gauss_half_range(40);
  std::vector<double> cosines = rule.nodes;
  for (const double mu : rule.nodes) cosines.push_back(-mu);
  for (const double mu : {-1.0, -0.5, -0.05, -1e-6, 1e-6}) cosines.push_back(mu);
  const CosineProjector projector(48, 241);
  for (const RoughDielectric& interface : kInterfaces) {
    Worst worst;
    for (const double from : cosines) {
      for (const double to : cosines) {
        for (int k = 0; k < projector.samples(); ++k) {
          compare(interface, from, to, projector.cos_angle(k), projector.sin_angle(k), worst);
        }
      }
    }
    if (interface.eta == 1.0) {
      EXPECT_EQ(worst.peak, 0.0);  // no interface: no BSDF value, as in microfacet.h
      EXPECT_EQ(worst.error, 0.0);
    } else {
      EXPECT_GT(worst.peak, 0.0);
      EXPECT_LE(worst.error, 1e-12 * worst.peak) << "eta " << interface.eta << ", sigma " << interface.sigma;
    }
  }
}

TEST(InterfaceAzimuthSweep, EqualsTheMicrofacetBsdfAtRandomPairs) {
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> cosine(-1.0, 1.0), azimuth(0.0, kPi);
  for (const RoughDielectric& interface : kInterfaces) {
    Worst worst;
    for (int i = 0; i < 200000; ++i) {
      const double phi = azimuth(random);
      compare(interface, cosine(random), cosine(random), std::cos(phi), std::sin(phi), worst);
    }
    EXPECT_LE(worst.error, 1e-12 * std::max(worst.peak, 1e-300))
        << "eta " << interface.eta << ", sigma " << interface.sigma;
  }
}

}  // namespace
}  // namespace skinlayer
