// A brute-force integral over the light's hemisphere for lobes whose masking falls as sqrt(mu) at the horizon (GGX's
// G2, for a grazing view or light): int g(omega) d omega with mu = t^2, d mu = 2 t dt, on `polar` Gauss-Legendre t
// times 2 `polar` azimuths. The view must lie in the xz-plane and g be even in y: the azimuth is folded onto [0, pi].
#pragma once

#include <cmath>
#include <functional>

#include "core/conventions.h"
#include "core/interfaces/microfacet.h"
#include "core/series/quadrature.h"

namespace skinlayer::test {

inline double over_graded_hemisphere(const std::function<double(const Vec3&)>& g, int polar) {
  const QuadratureRule t = gauss_legendre(polar, 0.0, 1.0), phi = gauss_legendre(2 * polar, 0.0, kPi);
  double sum = 0.0;
  for (std::size_t a = 0; a < t.nodes.size(); ++a) {
    const double mu = t.nodes[a] * t.nodes[a], weight = 2.0 * t.nodes[a] * t.weights[a];
    const double sine = std::sqrt(1.0 - mu * mu);
    for (std::size_t b = 0; b < phi.nodes.size(); ++b) {
      const Vec3 omega(sine * std::cos(phi.nodes[b]), sine * std::sin(phi.nodes[b]), mu);
      sum += 2.0 * weight * phi.weights[b] * g(omega);
    }
  }
  return sum;
}

}  // namespace skinlayer::test
