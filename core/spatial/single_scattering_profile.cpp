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

// Panel edges in d, the distance from the scattering point to the exit face, up to the layer's end: graded towards
// d = 0, where the exit directions of an annulus turn grazing, with `extra` edges added (sorted together).
std::vector<double> distance_edges(double tau, std::vector<double> extra = {}) {
  const double end = std::min(tau, kDepthCut);
  extra.insert(extra.end(), {0.0, 0.02, 0.1, 0.3, 1.0, 2.5, 5.0, 10.0, 20.0, kDepthCut});
  std::sort(extra.begin(), extra.end());
  std::vector<double> edges;
  for (const double edge : extra) {
    if (edge <= end && (edges.empty() || edge > edges.back())) edges.push_back(edge);
  }
  if (edges.back() < end) edges.push_back(end);
  return edges;
}

// int over d of f(d) on those panels, kNodes-point Gauss-Legendre (`unit`, on [0, 1]) each.
template <class Function>
double over_distance(const std::vector<double>& edges, const QuadratureRule& unit, const Function& f) {
  double total = 0.0;
  for (std::size_t e = 0; e + 1 < edges.size(); ++e) total += integrate_mapped(unit, edges[e], edges[e + 1], f);
  return total;
}

// e^-z at the scattering depth z for the distance d to the face.
double beam_at(double tau, LayerFace face, double d) { return std::exp(face == LayerFace::Top ? -d : -(tau - d)); }

// The scattering angle's cosine for an exit at polar angle cos(theta) through `face`: the beam travels down.
double scattering_cosine(LayerFace face, double cos_theta) { return face == LayerFace::Top ? -cos_theta : cos_theta; }

}  // namespace

double single_scattered_power(double tau, double albedo, double g, LayerFace face, double r0, double r1) {
  check(tau, albedo, g, face);
  if (!(r0 >= 0.0 && r1 >= r0)) throw std::invalid_argument("single scattering: the annulus needs 0 <= r0 <= r1");
  const QuadratureRule unit = gauss_legendre(kNodes, 0.0, 1.0);
  const double total = over_distance(distance_edges(tau), unit, [&](double d) {
    const double theta0 = std::atan(r0 / d), theta1 = std::isinf(r1) ? 0.5 * kPi : std::atan(r1 / d);
    if (theta1 <= theta0) return 0.0;
    return beam_at(tau, face, d) * integrate_mapped(unit, theta0, theta1, [&](double theta) {
             const double c = std::cos(theta);
             return henyey_greenstein(scattering_cosine(face, c), g) * std::exp(-d / c) * 2.0 * kPi * std::sin(theta);
           });
  });
  return albedo * total;
}

double single_scattered_density(double tau, double albedo, double g, LayerFace face, double r) {
  check(tau, albedo, g, face);
  if (!(r > 0.0 && std::isfinite(r))) throw std::invalid_argument("single scattering: the radius must be > 0");
  // The integrand peaks where d ~ r: edges at r 2^j beside the fixed ones.
  std::vector<double> around_r;
  for (int j = -3; j <= 4; ++j) around_r.push_back(r * std::ldexp(1.0, j));
  const double total = over_distance(distance_edges(tau, around_r), gauss_legendre(kNodes, 0.0, 1.0), [&](double d) {
    const double l = std::hypot(r, d);
    return beam_at(tau, face, d) * henyey_greenstein(scattering_cosine(face, d / l), g) * std::exp(-l) * d /
           (l * l * l);
  });
  return albedo * total;
}

double single_scattered_transform(double tau, double albedo, double g, LayerFace face, double k) {
  check(tau, albedo, g, face);
  if (!(k >= 0.0 && std::isfinite(k))) throw std::invalid_argument("single scattering: k must be finite and >= 0");
  const QuadratureRule unit = gauss_legendre(kNodes, 0.0, 1.0), cosines = gauss_legendre(2 * kNodes, 0.0, 1.0);
  const std::vector<double> edges = distance_edges(tau);
  const auto per_cosine = [&](double mu) {
    const double p = henyey_greenstein(scattering_cosine(face, mu), g);
    if (face == LayerFace::Top && std::isinf(tau)) {
      // int_0^inf e^{-z (1 + 1/mu)} J0(k z tan theta) dz = 1 / sqrt((1 + 1/mu)^2 + (k tan theta)^2)
      return p * mu / std::sqrt((1.0 + mu) * (1.0 + mu) + k * k * (1.0 - mu * mu));
    }
    const double tan_theta = std::sqrt(std::max(0.0, 1.0 - mu * mu)) / mu;
    return p * over_distance(edges, unit, [&](double d) {
             return beam_at(tau, face, d) * std::exp(-d / mu) * std::cyl_bessel_j(0.0, k * d * tan_theta);
           });
  };
  double total = 0.0;
  for (const auto& [a, b] : {std::pair{0.0, 0.1}, std::pair{0.1, 0.5}, std::pair{0.5, 1.0}}) {
    total += integrate_mapped(cosines, a, b, per_cosine);
  }
  return 2.0 * kPi * albedo * total;
}

}  // namespace skinlayer
