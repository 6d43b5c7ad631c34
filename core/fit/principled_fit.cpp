// docs/model.md §22.2: the Principled BSDF fitted to samples of a BRDF, its albedo at normal incidence matched.
#include "core/fit/principled_fit.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"

namespace skinlayer {
namespace {

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
  const Rgb rest = albedos.sum() - albedos.diffuse;
  const Rgb exact = (target - rest) / albedos.diffuse;
  p.base_color = exact.max(0.0).min(1.0);
  return albedos.diffuse * p.base_color + rest - target;
}

}  // namespace

PrincipledFit fit_principled(const BrdfFitTarget& target) {
  check_fit_target(target);
  const auto shape = [&](const Eigen::VectorXd& x) {
    PrincipledParameters p = with_shape(x);
    const Rgb miss = solve_base_color(p, target.albedo.front());
    return FittedShape{[p](const Vec3& i, const Vec3& o) { return principled_brdf_cosine_weighted(p, i, o); }, miss};
  };
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(5), hi = Eigen::VectorXd::Ones(5);
  lo(0) = lo(4) = kMinFittedRoughness;
  // A glossy start and a matte one.
  const Eigen::VectorXd starts[] = {(Eigen::VectorXd(5) << 0.5, 0.5, 0.0, 0.0, 0.1).finished(),
                                    (Eigen::VectorXd(5) << 0.9, 0.2, 0.2, 0.0, 0.1).finished()};
  const BoundedFit best = fit_shape(target, shape, starts, lo, hi);

  PrincipledFit fit;
  fit.parameters = with_shape(best.parameters);
  fit.albedo_miss = solve_base_color(fit.parameters, target.albedo.front());
  fit.albedo_matched = (fit.albedo_miss.abs() < 1e-12).all();
  fit.errors = fit_errors(
      target,
      [&](const Vec3& omega_i, const Vec3& omega_o) {
        return principled_brdf_cosine_weighted(fit.parameters, omega_i, omega_o);
      },
      [&](double theta) { return principled_albedo(fit.parameters, direction_from_angles(theta, 0.0)); });
  return fit;
}

}  // namespace skinlayer
