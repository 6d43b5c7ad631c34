// The unscattered light's first bounce off a bottom face in k-space (docs/model.md §21.17), against a closed form.
#include "core/spatial/bottom_bounce_transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <unsupported/Eigen/SpecialFunctions>

#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

// Diffuse light entering at a point through no top, over a Lambertian base of albedo A: the base sends back A of
// what reaches it, from the point where it lands and uniform in angle, so the bounce is the unscattered transmission
// twice over, a product in k-space:
//   B(k) = A [2 int_0^1 mu e^{-tau / mu} J0(k tau tan(theta)) d mu]^2,
// the azimuth's average of e^{-i k.x} over the landing points giving J0. At k = 0 that is A (2 E3(tau))^2.
double lambert_bounce(double albedo, double tau, double k) {
  const QuadratureRule rule = gauss_legendre(400, 0.0, 1.0);
  double crossing = 0.0;
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    const double mu = rule.nodes[i], tangent = std::sqrt(1.0 - mu * mu) / mu;
    crossing += 2.0 * rule.weights[i] * mu * std::exp(-tau / mu) * Eigen::numext::bessel_j0(k * tau * tangent);
  }
  return albedo * crossing * crossing;
}

TEST(BottomBounceTransform, LambertBaseUnderDiffuseLightIsTheCrossingSquared) {
  constexpr int kNodes = 96, kModes = 24;
  const LateralTopInterface top = open_top_interface(kNodes, kModes, Incidence::Diffuse);
  const LateralBottomFace base = lambert_bottom_face(0.7, kNodes, kModes);
  const LateralSlab slab{1.0, 0.5, 0.8};
  for (const double k : {0.0, 0.3, 1.0, 3.0}) {
    const double bounce = bottom_bounce_transform({&slab, 1}, top, base, k, kModes);
    const double closed = lambert_bounce(0.7, 1.0, k);
    std::printf("  k %.1f  bounce %.9f  closed form %.9f  (%+.1e)\n", k, bounce, closed, bounce / closed - 1.0);
    EXPECT_NEAR(bounce, closed, 1e-8 * lambert_bounce(0.7, 1.0, 0.0)) << k;
  }
}

}  // namespace
}  // namespace skinlayer
