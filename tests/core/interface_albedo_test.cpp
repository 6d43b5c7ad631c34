#include "core/interface_albedo.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/conventions.h"
#include "core/fresnel.h"
#include "core/quadrature.h"

namespace skinlayer {
namespace {

// Brute force over outgoing directions (independent of the slope-space change of variables).
InterfaceAlbedo integrate_outgoing(const RoughDielectric& interface, const Vec3& wi) {
  const QuadratureRule mu = gauss_legendre(600, 0.0, 1.0);
  const QuadratureRule phi = gauss_legendre(600, 0.0, 2.0 * kPi);
  const double side = wi.z() > 0 ? 1.0 : -1.0;
  InterfaceAlbedo sum{0.0, 0.0};
  for (int a = 0; a < mu.size(); ++a) {
    for (int b = 0; b < phi.size(); ++b) {
      const Vec3 w = direction_from_angles(std::acos(mu.nodes[a]), phi.nodes[b]);
      const double weight = mu.weights[a] * phi.weights[b] * mu.nodes[a];
      sum.reflectance += weight * microfacet_brdf(interface, wi, side * w);
      sum.transmittance += weight * microfacet_btdf(interface, wi, -side * w);
    }
  }
  return sum;
}

TEST(InterfaceAlbedo, AgreesWithBruteForceIntegrationOverOutgoingDirections) {
  for (double sigma : {0.3, 0.5, 1.0}) {
    const RoughDielectric interface{1.4, sigma};
    for (double side : {1.0, -1.0}) {
      for (double theta : {0.2, 0.8, 1.3}) {
        const Vec3 wi = side * direction_from_angles(theta, 0.0);
        const InterfaceAlbedo fast = interface_albedo(interface, wi);
        const InterfaceAlbedo slow = integrate_outgoing(interface, wi);
        EXPECT_NEAR(fast.reflectance, slow.reflectance, 2e-3) << sigma << " " << side << " " << theta;
        EXPECT_NEAR(fast.transmittance, slow.transmittance, 2e-3) << sigma << " " << side << " " << theta;
      }
    }
  }
}

TEST(InterfaceAlbedo, SmoothLimitIsFresnel) {
  const RoughDielectric interface{1.4, 0.05};
  const double theta = 0.5;
  const InterfaceAlbedo albedo = interface_albedo(interface, direction_from_angles(theta, 0.0));
  const double fresnel = fresnel_dielectric(std::cos(theta), 1.4);
  EXPECT_NEAR(albedo.reflectance, fresnel, 2e-3);
  EXPECT_NEAR(albedo.transmittance, 1.0 - fresnel, 2e-3);
}

TEST(InterfaceAlbedo, ShadowingOnlyRemovesEnergyAndIndexMatchIsTransparent) {
  for (double theta : {0.0, 0.7, 1.2, 1.5}) {
    for (double side : {1.0, -1.0}) {
      const InterfaceAlbedo albedo = interface_albedo({1.4, 0.5}, side * direction_from_angles(theta, 0.3));
      EXPECT_GE(albedo.loss(), -1e-9);
      EXPECT_LT(albedo.loss(), 0.35);
    }
  }
  const InterfaceAlbedo none = interface_albedo({1.0, 0.5}, direction_from_angles(0.7, 0.0));
  EXPECT_EQ(none.reflectance, 0.0);
  EXPECT_EQ(none.transmittance, 1.0);
}

}  // namespace
}  // namespace skinlayer
