// docs/model.md §22.2: the pairs a shader fit samples, and the errors it reports.
#include "core/fit/brdf_fit_target.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"
#include "core/series/quadrature.h"

namespace skinlayer {
std::vector<DirectionPair> fit_pairs(int polar) {
  const QuadratureRule mu = gauss_legendre(polar, 0.0, 1.0), phi = gauss_legendre(2 * polar, 0.0, 2.0 * kPi);
  // The cap about the mirror direction: psi = psi_max u^2 from it, on Gauss-Legendre u, so that the nodes crowd
  // where a sharp lobe peaks; the weight is sin(psi) d psi d phi with d psi = 2 psi_max u du.
  const double psi_max = degrees_to_radians(kMirrorCapDegrees);
  const QuadratureRule u = gauss_legendre(polar, 0.0, 1.0);
  std::vector<DirectionPair> pairs;
  for (int degrees = 0; degrees <= 80; degrees += 10) {
    const Vec3 light = direction_from_angles(degrees_to_radians(degrees), 0.0);
    for (std::size_t a = 0; a < mu.nodes.size(); ++a) {
      for (std::size_t b = 0; b < phi.nodes.size(); ++b) {
        pairs.push_back(
            {light, direction_from_angles(std::acos(mu.nodes[a]), phi.nodes[b]), mu.weights[a] * phi.weights[b]});
      }
    }
    const Vec3 mirror(-light.x(), 0.0, light.z());
    const Vec3 across = Vec3::UnitY(), along = across.cross(mirror);  // a frame about the mirror direction
    for (std::size_t a = 0; a < u.nodes.size(); ++a) {
      const double psi = psi_max * u.nodes[a] * u.nodes[a];
      for (std::size_t b = 0; b < phi.nodes.size(); ++b) {
        const Vec3 view =
            std::cos(psi) * mirror + std::sin(psi) * (std::cos(phi.nodes[b]) * along + std::sin(phi.nodes[b]) * across);
        if (view.z() <= 0.0) continue;
        const double weight = u.weights[a] * 2.0 * psi_max * u.nodes[a] * std::sin(psi) * phi.weights[b];
        pairs.push_back({light, view, weight});
      }
    }
  }
  return pairs;
}

void check_fit_target(const BrdfFitTarget& target) {
  const std::size_t n = target.pairs.size();
  if (n == 0 || target.brdf_cosine.size() != n || target.albedo.empty() ||
      target.albedo.size() != target.albedo_angles.size() || target.albedo_angles.front() != 0.0) {
    throw std::invalid_argument(
        "shader fit: needs one target value per pair and albedos at angles starting from normal incidence");
  }
}

FitErrors fit_errors(const BrdfFitTarget& target, const std::function<Rgb(const Vec3&, const Vec3&)>& brdf_cosine,
                     const std::function<Rgb(double theta)>& albedo) {
  FitErrors errors;
  Rgb peak = Rgb::Zero(), squared = Rgb::Zero();
  double weights = 0.0;
  for (const Rgb& value : target.brdf_cosine) peak = peak.max(value.abs());
  for (std::size_t k = 0; k < target.pairs.size(); ++k) {
    const DirectionPair& pair = target.pairs[k];
    const Rgb difference = (brdf_cosine(pair.omega_i, pair.omega_o) - target.brdf_cosine[k]).abs();
    squared += pair.weight * difference.square();
    weights += pair.weight;
    errors.lobe_worst = errors.lobe_worst.max(difference);
  }
  errors.lobe_rms = (squared / weights).sqrt() / peak;
  errors.lobe_worst /= peak;
  Rgb albedo_squared = Rgb::Zero();
  for (std::size_t a = 0; a < target.albedo.size(); ++a) {
    const Rgb fitted = albedo(target.albedo_angles[a]);
    errors.albedo_angles.push_back(target.albedo_angles[a]);
    errors.albedo_fitted.push_back(fitted);
    errors.albedo_target.push_back(target.albedo[a]);
    const Rgb relative = (fitted - target.albedo[a]).abs() / target.albedo[a];
    albedo_squared += relative.square();
    errors.albedo_worst = errors.albedo_worst.max(relative);
  }
  errors.albedo_rms = (albedo_squared / static_cast<double>(target.albedo.size())).sqrt();
  return errors;
}

BoundedFit fit_shape(const BrdfFitTarget& target, const std::function<FittedShape(const Eigen::VectorXd&)>& shape,
                     std::span<const Eigen::VectorXd> starts, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  check_fit_target(target);
  const std::size_t n = target.pairs.size();
  const auto residuals = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    const FittedShape fitted = shape(x);
    r.tail<3>() = kAlbedoMissWeight * fitted.albedo_miss.matrix();
    for (std::size_t k = 0; k < n; ++k) {
      const DirectionPair& pair = target.pairs[k];
      const Rgb difference = fitted.brdf_cosine(pair.omega_i, pair.omega_o) - target.brdf_cosine[k];
      r.segment<3>(static_cast<Eigen::Index>(3 * k)) = std::sqrt(pair.weight) * difference.matrix();
    }
  };
  const int count = static_cast<int>(3 * n + 3);
  BoundedFit best;
  for (const Eigen::VectorXd& start : starts) {
    BoundedFit fit = fit_in_box(residuals, count, start, lo, hi);
    if (best.parameters.size() == 0 || fit.norm() < best.norm()) best = std::move(fit);
  }
  return best;
}

Rgb color_for_albedo(const std::function<Rgb(const Rgb&)>& albedo, const Rgb& target, Rgb& miss) {
  Rgb lo = Rgb::Zero(), hi = Rgb::Ones();
  for (int step = 0; step < 52; ++step) {
    const Rgb middle = 0.5 * (lo + hi);
    const Rgb value = albedo(middle);
    for (int c = 0; c < 3; ++c) (value(c) < target(c) ? lo(c) : hi(c)) = middle(c);
  }
  Rgb color = 0.5 * (lo + hi);
  const Rgb darkest = albedo(Rgb::Zero()), brightest = albedo(Rgb::Ones());
  for (int c = 0; c < 3; ++c) {
    if (target(c) <= darkest(c)) color(c) = 0.0;
    if (target(c) >= brightest(c)) color(c) = 1.0;
  }
  const Rgb off = albedo(color) - target;
  miss = ((color > 0.0) && (color < 1.0)).select(Rgb::Zero(), off);
  return color;
}

}  // namespace skinlayer
