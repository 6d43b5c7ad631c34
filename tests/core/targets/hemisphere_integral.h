// A brute-force integral over the light's hemisphere, for the target shaders' tests: int g(omega_i) d omega_i on
// `polar` Gauss-Legendre cosines times 2 `polar` azimuths.
#pragma once

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

}  // namespace skinlayer::test
