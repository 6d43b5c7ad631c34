// docs/model.md §21.6: single scattering in an open layer, by Gauss-Legendre panels in the distance to the exit face
// and in the exit angle.
#include "core/spatial/single_scattering_profile.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/conventions.h"
#include "core/medium/henyey_greenstein.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

constexpr int kNodes = 32;
// Beyond 45 mean free paths e^-d is below 1e-19: the end of a semi-infinite layer.
constexpr double kDepthCut = 45.0;

void check(double tau, double albedo, double g, LayerFace face) {
  if (!(tau >= 0.0) || !(albedo >= 0.0 && albedo <= 1.0) || !(std::abs(g) <= 0.95)) {
    throw std::invalid_argument("single scattering: tau >= 0, albedo in [0, 1] and g in [-0.95, 0.95]");
  }
  if (face == LayerFace::Bottom && std::isinf(tau)) {
    throw std::invalid_argument("single scattering: a semi-infinite layer has no bottom face");
  }
}

// Panels in d, the distance from the scattering point to the exit face, graded towards d = 0 where the exit
// directions of an annulus turn grazing.
std::vector<QuadratureRule> distance_panels(double tau) {
  const double end = std::min(tau, kDepthCut);
  std::vector<QuadratureRule> panels;
  double from = 0.0;
  for (const double to : {0.02, 0.1, 0.3, 1.0, 2.5, 5.0, 10.0, 20.0, kDepthCut}) {
    const double upper = std::min(to, end);
    if (upper > from) panels.push_back(gauss_legendre(kNodes, from, upper));
    from = upper;
    if (from >= end) break;
  }
  return panels;
}

// e^-z at the scattering depth z for the distance d to the face.
double beam_at(double tau, LayerFace face, double d) { return std::exp(face == LayerFace::Top ? -d : -(tau - d)); }

// The scattering angle's cosine for an exit at polar angle cos(theta) through `face`: the beam travels down.
double scattering_cosine(LayerFace face, double cos_theta) { return face == LayerFace::Top ? -cos_theta : cos_theta; }

}  // namespace

double single_scattered_power(double tau, double albedo, double g, LayerFace face, double r0, double r1) {
  check(tau, albedo, g, face);
  if (!(r0 >= 0.0 && r1 >= r0)) throw std::invalid_argument("single scattering: the annulus needs 0 <= r0 <= r1");
  double total = 0.0;
  for (const QuadratureRule& panel : distance_panels(tau)) {
    for (int i = 0; i < panel.size(); ++i) {
      const double d = panel.nodes[static_cast<std::size_t>(i)];
      const double theta0 = std::atan(r0 / d), theta1 = std::isinf(r1) ? 0.5 * kPi : std::atan(r1 / d);
      if (theta1 <= theta0) continue;
      const QuadratureRule angles = gauss_legendre(kNodes, theta0, theta1);
      double inner = 0.0;
      for (int j = 0; j < angles.size(); ++j) {
        const double theta = angles.nodes[static_cast<std::size_t>(j)];
        const double c = std::cos(theta);
        inner += angles.weights[static_cast<std::size_t>(j)] * henyey_greenstein(scattering_cosine(face, c), g) *
                 std::exp(-d / c) * 2.0 * kPi * std::sin(theta);
      }
      total += panel.weights[static_cast<std::size_t>(i)] * beam_at(tau, face, d) * inner;
    }
  }
  return albedo * total;
}

double single_scattered_density(double tau, double albedo, double g, LayerFace face, double r) {
  check(tau, albedo, g, face);
  if (!(r > 0.0 && std::isfinite(r))) throw std::invalid_argument("single scattering: the radius must be > 0");
  // The integrand peaks where d ~ r: panels at r 2^j, then the fixed ones.
  std::vector<double> bounds = {0.0, 0.02, 0.1, 0.3, 1.0, 2.5, 5.0, 10.0, 20.0, kDepthCut};
  for (int j = -3; j <= 4; ++j) bounds.push_back(r * std::ldexp(1.0, j));
  const double end = std::min(tau, kDepthCut);
  std::sort(bounds.begin(), bounds.end());
  double total = 0.0;
  for (std::size_t b = 0; b + 1 < bounds.size(); ++b) {
    const double from = bounds[b], to = std::min(bounds[b + 1], end);
    if (to <= from) continue;
    const QuadratureRule panel = gauss_legendre(kNodes, from, to);
    for (int i = 0; i < panel.size(); ++i) {
      const double d = panel.nodes[static_cast<std::size_t>(i)];
      const double l = std::hypot(r, d);
      total += panel.weights[static_cast<std::size_t>(i)] * beam_at(tau, face, d) *
               henyey_greenstein(scattering_cosine(face, d / l), g) * std::exp(-l) * d / (l * l * l);
    }
  }
  return albedo * total;
}

double single_scattered_transform(double tau, double albedo, double g, LayerFace face, double k) {
  check(tau, albedo, g, face);
  if (!(k >= 0.0 && std::isfinite(k))) throw std::invalid_argument("single scattering: k must be finite and >= 0");
  double total = 0.0;
  for (const auto& [a, b] : {std::pair{0.0, 0.1}, std::pair{0.1, 0.5}, std::pair{0.5, 1.0}}) {
    const QuadratureRule cosines = gauss_legendre(2 * kNodes, a, b);
    for (int j = 0; j < cosines.size(); ++j) {
      const double mu = cosines.nodes[static_cast<std::size_t>(j)];
      const double p = henyey_greenstein(scattering_cosine(face, mu), g);
      double inner = 0.0;
      if (face == LayerFace::Top && std::isinf(tau)) {
        // int_0^inf e^{-z (1 + 1/mu)} J0(k z tan theta) dz = 1 / sqrt((1 + 1/mu)^2 + (k tan theta)^2)
        inner = mu / std::sqrt((1.0 + mu) * (1.0 + mu) + k * k * (1.0 - mu * mu));
      } else {
        const double tan_theta = std::sqrt(std::max(0.0, 1.0 - mu * mu)) / mu;
        for (const QuadratureRule& panel : distance_panels(tau)) {
          for (int i = 0; i < panel.size(); ++i) {
            const double d = panel.nodes[static_cast<std::size_t>(i)];
            inner += panel.weights[static_cast<std::size_t>(i)] * beam_at(tau, face, d) * std::exp(-d / mu) *
                     std::cyl_bessel_j(0.0, k * d * tan_theta);
          }
        }
      }
      total += cosines.weights[static_cast<std::size_t>(j)] * p * inner;
    }
  }
  return 2.0 * kPi * albedo * total;
}

}  // namespace skinlayer
