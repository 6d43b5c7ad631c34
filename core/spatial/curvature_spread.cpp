// docs/model.md §21.13: a spatial profile pre-integrated over a sphere's curvature.
#include "core/spatial/curvature_spread.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

// int_0^{2 pi} max(0, a + b cos(beta)) d beta, b >= 0.
double azimuth_integral(double a, double b) {
  if (a >= b) return 2.0 * kPi * a;
  if (a <= -b) return 0.0;
  return 2.0 * (a * std::acos(-a / b) + std::sqrt(b * b - a * a));
}

}  // namespace

CurvatureSpread::CurvatureSpread(std::span<const double> edges, std::span<const double> powers, double sphere_radius) {
  if (!(sphere_radius > 0.0 && std::isfinite(sphere_radius))) {
    throw std::invalid_argument("curvature spread: the sphere radius must be finite and > 0");
  }
  if (edges.size() != powers.size() + 1 || edges.empty() || edges.front() != 0.0 ||
      !std::is_sorted(edges.begin(), edges.end())) {
    throw std::invalid_argument("curvature spread: edges must increase from 0, one more than the powers");
  }
  const double diameter = 2.0 * sphere_radius;
  const QuadratureRule unit = gauss_legendre(8, 0.0, 1.0);
  double total = 0.0;
  for (std::size_t i = 0; i < powers.size(); ++i) {
    if (!(powers[i] >= 0.0) || !std::isfinite(powers[i])) {
      throw std::invalid_argument("curvature spread: powers must be finite and >= 0");
    }
    const double d0 = edges[i], d1 = std::min(edges[i + 1], diameter);
    if (d1 <= d0 || powers[i] == 0.0) continue;
    // The share of the annulus within the diameter, by area (the power is taken as even over the annulus).
    const double kept = (d1 * d1 - d0 * d0) / (edges[i + 1] * edges[i + 1] - d0 * d0);
    Band band;
    band.weight = powers[i] * kept;
    const double a0 = 2.0 * std::asin(d0 / diameter), a1 = 2.0 * std::asin(std::min(1.0, d1 / diameter));
    double area = 0.0;
    for (int q = 0; q < unit.size(); ++q) {
      const double alpha = a0 + (a1 - a0) * unit.nodes[static_cast<std::size_t>(q)];
      const double w = (a1 - a0) * unit.weights[static_cast<std::size_t>(q)] * std::sin(alpha);
      band.alpha.push_back(alpha);
      band.factor.push_back(w);
      area += w;
    }
    for (double& f : band.factor) f /= 2.0 * kPi * area;
    total += band.weight;
    bands_.push_back(std::move(band));
  }
  if (!(total > 0.0)) throw std::invalid_argument("curvature spread: no light within the sphere's diameter");
  for (Band& band : bands_) band.weight /= total;
}

double CurvatureSpread::operator()(double theta) const {
  const double c = std::cos(theta), s = std::sin(theta);
  double spread = 0.0;
  for (const Band& band : bands_) {
    double average = 0.0;
    for (std::size_t q = 0; q < band.alpha.size(); ++q) {
      average += band.factor[q] * azimuth_integral(std::cos(band.alpha[q]) * c, std::sin(band.alpha[q]) * s);
    }
    spread += band.weight * average;
  }
  return spread;
}

std::vector<double> CurvatureSpread::sampled(int count) const {
  if (count < 2) throw std::invalid_argument("curvature spread: needs at least 2 samples");
  std::vector<double> values;
  for (int k = 0; k < count; ++k) values.push_back((*this)(kPi * k / (count - 1)));
  return values;
}

}  // namespace skinlayer
