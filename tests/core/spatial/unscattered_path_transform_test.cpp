// Light crossing a stack unscattered through its faces, in k-space (docs/model.md §21.17), against closed forms.
#include "core/spatial/unscattered_path_transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <unsupported/Eigen/SpecialFunctions>

#include "core/series/quadrature.h"
#include "core/spatial/lateral_bottom_face.h"
#include "core/spatial/lateral_top_interface.h"

namespace skinlayer {
namespace {

constexpr int kNodes = 96, kModes = 24;

// Diffuse light entering at a point through no top crosses optical depth tau (geometric depth H) unscattered with
//   C(k) = 2 int_0^1 mu e^{-tau / mu} J0(k H tan(theta)) d mu,
// the azimuth's average of e^{-i k.x} over the landing points giving J0. At k = 0 that is 2 E3(tau).
double crossing(double tau, double height, double k) {
  const QuadratureRule rule = gauss_legendre(400, 0.0, 1.0);
  double sum = 0.0;
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    const double mu = rule.nodes[i], tangent = std::sqrt(1.0 - mu * mu) / mu;
    sum += 2.0 * rule.weights[i] * mu * std::exp(-tau / mu) * Eigen::numext::bessel_j0(k * height * tangent);
  }
  return sum;
}

TEST(UnscatteredPathTransform, OneLegIsTheDiffuseCrossing) {
  const LateralTopInterface top = open_top_interface(kNodes, kModes, Incidence::Diffuse);
  const UnscatteredLeg leg{1.0, 0.5};  // a slab twice as dense as the first one's mean free path
  for (const double k : {0.0, 0.3, 1.0, 3.0}) {
    const double path = unscattered_path_transform(top.source, {&leg, 1}, {}, top.exit, k, kModes);
    EXPECT_NEAR(path, crossing(1.0, 0.5, k), 1e-8 * crossing(1.0, 0.5, 0.0)) << k;
  }
}

// A Lambertian base of albedo A sends back A of what reaches it, from where it lands and uniform in angle, so the
// bounce is the crossing twice over, a product in k-space: A C(k)^2.
TEST(UnscatteredPathTransform, BounceOffALambertBaseIsTheCrossingSquared) {
  const LateralTopInterface top = open_top_interface(kNodes, kModes, Incidence::Diffuse);
  const LateralBottomFace base = lambert_bottom_face(0.7, kNodes, kModes);
  const UnscatteredLeg legs[] = {{1.0, 1.0}, {1.0, 1.0}};
  const std::vector<Eigen::MatrixXd>* faces[] = {&base.reflection};
  for (const double k : {0.0, 0.3, 1.0, 3.0}) {
    const double bounce = unscattered_path_transform(top.source, legs, faces, top.exit, k, kModes);
    const double closed = 0.7 * std::pow(crossing(1.0, 1.0, k), 2);
    std::printf("  k %.1f  bounce %.9f  closed form %.9f  (%+.1e)\n", k, bounce, closed, bounce / closed - 1.0);
    EXPECT_NEAR(bounce, closed, 1e-8 * 0.7 * std::pow(crossing(1.0, 1.0, 0.0), 2)) << k;
  }
}

// A face that passes every mode unchanged joins two legs into one.
TEST(UnscatteredPathTransform, ATransparentFaceJoinsTheLegs) {
  const LateralTopInterface top = open_top_interface(kNodes, kModes, Incidence::Diffuse);
  const std::vector<Eigen::MatrixXd> transparent(kModes, Eigen::MatrixXd::Identity(kNodes, kNodes));
  const UnscatteredLeg split[] = {{0.4, 0.4}, {0.6, 0.3}}, whole{1.0, 0.7};
  const std::vector<Eigen::MatrixXd>* faces[] = {&transparent};
  for (const double k : {0.0, 1.0, 4.0}) {
    EXPECT_NEAR(unscattered_path_transform(top.source, split, faces, top.exit, k, kModes),
                unscattered_path_transform(top.source, {&whole, 1}, {}, top.exit, k, kModes), 1e-12)
        << k;
  }
  EXPECT_THROW(unscattered_path_transform(top.source, split, {}, top.exit, 1.0, kModes), std::invalid_argument);
}

}  // namespace
}  // namespace skinlayer
