// docs/model.md §22.4: OpenPBR Surface fitted to samples of a BRDF, its albedo at normal incidence matched.
#include "core/fit/openpbr_fit.h"

#include <cmath>

#include "core/fit/surface_fit.h"

namespace skinlayer {
namespace {

// The fitted vector: specular roughness and weight, diffuse roughness, fuzz weight and roughness, and with a coat
// the coat's roughness.
int fitted_count(const OpenPbrFitSettings& settings) { return settings.coat ? 6 : 5; }

OpenPbrParameters with_shape(const Eigen::VectorXd& x, const OpenPbrFitSettings& settings) {
  OpenPbrParameters p;
  p.specular_ior = settings.specular_ior;
  p.specular_roughness = x(0);
  p.specular_weight = x(1);
  p.base_diffuse_roughness = x(2);
  p.fuzz_weight = x(3);
  p.fuzz_roughness = x(4);
  p.coat_weight = settings.coat ? 1.0 : 0.0;
  p.coat_ior = settings.coat_ior;
  p.coat_roughness = settings.coat ? x(5) : 0.0;
  p.subsurface_weight = settings.subsurface_weight;
  return p;
}

// The colour that gives the target albedo at normal incidence (color_for_albedo), and what the albedo misses where
// [0, 1] holds no such colour.
OpenPbrSurface with_solved_color(const OpenPbrSurface& surface, const Rgb& target, Rgb& miss) {
  const Rgb color = color_for_albedo(
      [&](const Rgb& diffuse) { return surface.albedo_with_diffuse_color(1.0, diffuse); }, target, miss);
  return surface.with_diffuse_colors(color, color);
}

// The surface of the shape x with its colour solved; the miss goes to `miss`.
OpenPbrSurface solved_surface(const Eigen::VectorXd& x, const OpenPbrFitSettings& settings, const Rgb& target,
                              Rgb& miss) {
  return with_solved_color(OpenPbrSurface(with_shape(x, settings)), target, miss);
}

}  // namespace

OpenPbrFit fit_openpbr(const BrdfFitTarget& target, const OpenPbrFitSettings& settings) {
  const int fitted = fitted_count(settings);
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(fitted), hi = Eigen::VectorXd::Ones(fitted);
  lo(0) = lo(4) = kMinFittedRoughness;
  if (settings.coat) lo(5) = kMinFittedRoughness;
  // A glossy start and a matte one.
  const Eigen::VectorXd starts[] = {(Eigen::VectorXd(6) << 0.4, 1.0, 0.0, 0.0, 0.5, 0.3).finished().head(fitted),
                                    (Eigen::VectorXd(6) << 0.8, 0.5, 0.5, 0.3, 0.5, 0.3).finished().head(fitted)};
  const auto found = fit_surface(
      target,
      [&](const Eigen::VectorXd& x, Rgb& miss) { return solved_surface(x, settings, target.albedo.front(), miss); },
      starts, lo, hi);
  return {found.surface.parameters(), found.albedo_matched, found.albedo_miss, found.errors};
}

}  // namespace skinlayer
