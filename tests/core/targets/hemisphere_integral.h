// A brute-force integral over the light's hemisphere, for the target shaders' tests: int g(omega_i) d omega_i on
// `polar` Gauss-Legendre cosines times 2 `polar` azimuths.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/conventions.h"
#include "core/series/quadrature.h"

namespace skinlayer::test {

template <typename Value>
Value over_hemisphere(const std::function<Value(const Vec3&)>& g, int polar, Value zero) {
  const QuadratureRule mu = gauss_legendre(polar, 0.0, 1.0), phi = gauss_legendre(2 * polar, 0.0, 2.0 * kPi);
  Value sum = zero;
  for (std::size_t a = 0; a < mu.nodes.size(); ++a) {
    const double sine = std::sqrt(1.0 - mu.nodes[a] * mu.nodes[a]);
    for (std::size_t b = 0; b < phi.nodes.size(); ++b) {
      const Vec3 omega(sine * std::cos(phi.nodes[b]), sine * std::sin(phi.nodes[b]), mu.nodes[a]);
      sum = sum + mu.weights[a] * phi.weights[b] * g(omega);
    }
  }
  return sum;
}

// A lobe that is a density over the light scaled by its albedo at the view (an LTC sheen): for roughness 0.1, 0.5
// and 1 and views 0, 0.6, 1.2 and 1.5 rad from the normal, the integral of f cos(theta_i) over the light is
// albedo(mu_o, r) within 0.2% (plus `floor`), and that albedo is a fraction.
inline void expect_lobe_integrates_to_its_albedo(
    const std::function<double(double roughness, const Vec3& light, const Vec3& view)>& cosine_weighted,
    const std::function<double(double mu_o, double roughness)>& albedo_of, double floor) {
  for (const double roughness : {0.1, 0.5, 1.0}) {
    for (const double theta : {0.0, 0.6, 1.2, 1.5}) {
      const Vec3 view = direction_from_angles(theta, 0.4);
      const double integral =
          over_hemisphere<double>([&](const Vec3& light) { return cosine_weighted(roughness, light, view); }, 128, 0.0);
      const double albedo = albedo_of(view.z(), roughness);
      EXPECT_NEAR(integral, albedo, 2e-3 * albedo + floor) << roughness << " " << theta;
      EXPECT_GE(albedo, 0.0);
      EXPECT_LT(albedo, 1.0);
    }
  }
}

}  // namespace skinlayer::test
