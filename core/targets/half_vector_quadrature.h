// Integrals over the light's hemisphere of a microfacet lobe, taken over half vectors (docs/model.md §22.1.1), the way
// ggx_lobe.h's microfacet_lobe_albedo takes them, for integrands evaluated many times (Cycles' tables): the rules are
// computed once, and the view lies in the xz-plane at azimuth 0 so that, for an integrand even in y, the half
// vector's azimuth folds onto [0, pi]. With omega_i = 2 (omega_o.h) h - omega_o and d omega_i = 4 (omega_o.h)
// d omega_h (Walter et al. 2007, eq. 14): at each of `polar` azimuths phi of h the light leaves the hemisphere where
// a sin(2 theta_h) + b cos(2 theta_h) = 0 (a = sin(theta_o) cos(phi), b = cos(theta_o)); `polar` Gauss-Legendre nodes
// stop there, spread between as a distribution of width `width` in tan(theta_h) spreads them: theta_h =
// atan(width tan(v pi / 2)), v in [0, v_max].
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "core/conventions.h"
#include "core/interfaces/microfacet.h"
#include "core/series/quadrature.h"

namespace skinlayer {

class HalfVectorQuadrature {
 public:
  explicit HalfVectorQuadrature(int polar)
      : azimuths_(gauss_legendre(polar, 0.0, kPi)), unit_(gauss_legendre(polar, 0.0, 1.0)) {}

  // int g(omega_i) d omega_i over the upper hemisphere, the view at cosine mu_o in the xz-plane; g(omega_i) must be
  // even in omega_i.y and is called only above the horizon. g returns a double or an Eigen array (several integrals
  // on the same nodes).
  template <class Integrand>
  auto integrate(double mu_o, double width, const Integrand& g) const {
    using Value = std::decay_t<decltype(g(Vec3::UnitZ()))>;
    const double mu = std::clamp(mu_o, 0.0, 1.0), sine = std::sqrt(1.0 - mu * mu);
    const Vec3 view(sine, 0.0, mu);
    Value sum;
    if constexpr (std::is_arithmetic_v<Value>) {
      sum = 0.0;
    } else {
      sum = Value::Zero();
    }
    for (std::size_t b = 0; b < azimuths_.nodes.size(); ++b) {
      const double phi = azimuths_.nodes[b], cos_phi = std::cos(phi), sin_phi = std::sin(phi);
      const double theta_max = 0.5 * (0.5 * kPi + std::atan2(sine * cos_phi, mu));
      const double v_max = 2.0 * kInvPi * std::atan(std::tan(theta_max) / width);
      for (std::size_t a = 0; a < unit_.nodes.size(); ++a) {
        const double v = v_max * unit_.nodes[a], t = std::tan(0.5 * kPi * v), theta = std::atan(width * t);
        const double dtheta_dv = width * 0.5 * kPi * (1.0 + t * t) / (1.0 + width * width * t * t);
        const double sin_theta = std::sin(theta);
        const Vec3 h(sin_theta * cos_phi, sin_theta * sin_phi, std::cos(theta));
        const double cos_oh = view.dot(h);
        if (cos_oh <= 0.0) continue;
        const Vec3 light = 2.0 * cos_oh * h - view;
        if (light.z() <= 0.0) continue;
        // 2: the folded azimuths (pi, 2 pi).
        const double weight =
            2.0 * v_max * unit_.weights[a] * dtheta_dv * sin_theta * azimuths_.weights[b] * 4.0 * cos_oh;
        sum += weight * g(light);
      }
    }
    return sum;
  }

 private:
  QuadratureRule azimuths_, unit_;
};

}  // namespace skinlayer
