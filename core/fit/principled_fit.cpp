// docs/model.md §22.2: the Principled BSDF fitted to samples of a BRDF, its albedo at normal incidence matched.
#include "core/fit/principled_fit.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"
#include "core/fit/bounded_least_squares.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

Vec3 direction(double cos_theta, double phi) {
  const double sine = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return {sine * std::cos(phi), sine * std::sin(phi), cos_theta};
}

// The fitted parameters: roughness, specular, sheen, clearcoat, clearcoat roughness. Metal and the tints stay 0, so
// that only the diffuse lobe depends on the base colour.
PrincipledParameters with_shape(const Eigen::VectorXd& x) {
  PrincipledParameters p;
  p.roughness = x(0);
  p.specular = x(1);
  p.sheen = x(2);
  p.sheen_tint = 0.0;
  p.clearcoat = x(3);
  p.clearcoat_roughness = x(4);
  return p;
}

// The base colour that gives the target albedo at normal incidence, clamped to [0, 1]; returns what the albedo then
// misses (zero where no clamp was needed): the other lobes alone reflect too much, or the brightest colour too little.
Rgb solve_base_color(PrincipledParameters& p, const Rgb& target) {
  p.base_color = Rgb::Ones();
  const PrincipledLobes albedos = principled_lobe_albedos(p, Vec3::UnitZ());
  const Rgb rest = albedos.sheen + albedos.specular + albedos.clearcoat;
  const Rgb exact = (target - rest) / albedos.diffuse;
  p.base_color = exact.max(0.0).min(1.0);
  return albedos.diffuse * p.base_color + rest - target;
}

// The weight of the albedo's miss among the residuals: large enough that the fit leaves a region where the colour
// cannot match it (against lobe residuals of about sqrt(weight) f cos, ~0.1 each).
constexpr double kAlbedoMissWeight = 30.0;

}  // namespace

std::vector<DirectionPair> principled_fit_pairs(int polar) {
  const QuadratureRule mu = gauss_legendre(polar, 0.0, 1.0), phi = gauss_legendre(2 * polar, 0.0, 2.0 * kPi);
  // The cap about the mirror direction: psi = psi_max u^2 from it, on Gauss-Legendre u, so that the nodes crowd
  // where a sharp lobe peaks; the weight is sin(psi) d psi d phi with d psi = 2 psi_max u du.
  const double psi_max = degrees_to_radians(kMirrorCapDegrees);
  const QuadratureRule u = gauss_legendre(polar, 0.0, 1.0);
  std::vector<DirectionPair> pairs;
  for (int degrees = 0; degrees <= 80; degrees += 10) {
    const Vec3 light = direction(std::cos(degrees_to_radians(degrees)), 0.0);
    for (std::size_t a = 0; a < mu.nodes.size(); ++a) {
      for (std::size_t b = 0; b < phi.nodes.size(); ++b) {
        pairs.push_back({light, direction(mu.nodes[a], phi.nodes[b]), mu.weights[a] * phi.weights[b]});
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

PrincipledFit fit_principled(const PrincipledFitTarget& target) {
  const std::size_t n = target.pairs.size();
  if (n == 0 || target.brdf_cosine.size() != n || target.albedo.empty() ||
      target.albedo.size() != target.albedo_angles.size() || target.albedo_angles.front() != 0.0) {
    throw std::invalid_argument(
        "fit_principled: needs one target value per pair and albedos at angles starting from normal incidence");
  }
  const auto residuals = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    PrincipledParameters p = with_shape(x);
    r.tail<3>() = kAlbedoMissWeight * solve_base_color(p, target.albedo.front()).matrix();
    for (std::size_t k = 0; k < n; ++k) {
      const DirectionPair& pair = target.pairs[k];
      const Rgb difference = principled_brdf_cosine_weighted(p, pair.omega_i, pair.omega_o) - target.brdf_cosine[k];
      r.segment<3>(static_cast<Eigen::Index>(3 * k)) = std::sqrt(pair.weight) * difference.matrix();
    }
  };
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(5), hi = Eigen::VectorXd::Ones(5);
  lo(0) = lo(4) = kMinFittedRoughness;
  const int count = static_cast<int>(3 * n + 3);
  // Two starts, a glossy and a matte one, as the least squares find the nearest minimum.
  BoundedFit best = fit_in_box(residuals, count, (Eigen::VectorXd(5) << 0.5, 0.5, 0.0, 0.0, 0.1).finished(), lo, hi);
  const BoundedFit matte =
      fit_in_box(residuals, count, (Eigen::VectorXd(5) << 0.9, 0.2, 0.2, 0.0, 0.1).finished(), lo, hi);
  if (matte.norm() < best.norm()) best = matte;

  PrincipledFit fit;
  fit.parameters = with_shape(best.parameters);
  fit.albedo_miss = solve_base_color(fit.parameters, target.albedo.front());
  fit.albedo_matched = (fit.albedo_miss.abs() < 1e-12).all();
  Rgb peak = Rgb::Zero(), squared = Rgb::Zero();
  double weights = 0.0;
  for (std::size_t k = 0; k < n; ++k) peak = peak.max(target.brdf_cosine[k].abs());
  for (std::size_t k = 0; k < n; ++k) {
    const DirectionPair& pair = target.pairs[k];
    const Rgb difference =
        (principled_brdf_cosine_weighted(fit.parameters, pair.omega_i, pair.omega_o) - target.brdf_cosine[k]).abs();
    squared += pair.weight * difference.square();
    weights += pair.weight;
    fit.lobe_worst = fit.lobe_worst.max(difference);
  }
  fit.lobe_rms = (squared / weights).sqrt() / peak;
  fit.lobe_worst /= peak;
  Rgb albedo_squared = Rgb::Zero();
  for (std::size_t a = 0; a < target.albedo.size(); ++a) {
    const Rgb relative =
        (principled_albedo(fit.parameters, direction(std::cos(target.albedo_angles[a]), 0.0)) - target.albedo[a])
            .abs() /
        target.albedo[a];
    albedo_squared += relative.square();
    fit.albedo_worst = fit.albedo_worst.max(relative);
  }
  fit.albedo_rms = (albedo_squared / static_cast<double>(target.albedo.size())).sqrt();
  return fit;
}

}  // namespace skinlayer
