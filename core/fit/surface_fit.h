// The fit a shader model with precomputed tables takes (docs/model.md §22.2, §22.4): the OpenPBR, glTF and today's
// Principled fits differ only in their parameter vectors, bounds and starts. `solved(x, miss)` builds the surface of
// the parameter vector x with its colour already solved for the target's albedo at normal incidence, and puts what
// that albedo misses in `miss`; the least squares of fit_shape (brdf_fit_target.h) choose x, and the errors are
// those of the surface found. Surface: brdf_cosine_weighted(omega_i, omega_o) and albedo(mu_o).
#pragma once

#include <cmath>
#include <span>

#include "core/fit/brdf_fit_target.h"

namespace skinlayer {

template <typename Surface>
struct SurfaceFit {
  Surface surface;
  Rgb albedo_miss = Rgb::Zero();  // the fitted albedo at normal incidence less the target's (0 where matched)
  bool albedo_matched = true;
  FitErrors errors;
};

template <typename Solved>
auto fit_surface(const BrdfFitTarget& target, const Solved& solved, std::span<const Eigen::VectorXd> starts,
                 const Eigen::VectorXd& lo, const Eigen::VectorXd& hi) {
  check_fit_target(target);
  const auto shape = [&](const Eigen::VectorXd& x) {
    Rgb miss;
    const auto surface = solved(x, miss);
    return FittedShape{[surface](const Vec3& i, const Vec3& o) { return surface.brdf_cosine_weighted(i, o); }, miss};
  };
  const BoundedFit best = fit_shape(target, shape, starts, lo, hi);
  Rgb miss;
  auto surface = solved(best.parameters, miss);
  const FitErrors errors = fit_errors(
      target, [&](const Vec3& omega_i, const Vec3& omega_o) { return surface.brdf_cosine_weighted(omega_i, omega_o); },
      [&](double theta) { return surface.albedo(std::cos(theta)); });
  const bool matched = (miss.abs() < 1e-9).all();
  return SurfaceFit<decltype(surface)>{std::move(surface), miss, matched, errors};
}

}  // namespace skinlayer
