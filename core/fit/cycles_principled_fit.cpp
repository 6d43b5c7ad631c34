// docs/model.md §22.2: Blender 4.x-5.x's Principled BSDF fitted to samples of a BRDF, its albedo at normal incidence
// matched.
#include "core/fit/cycles_principled_fit.h"

#include "core/fit/surface_fit.h"

namespace skinlayer {
namespace {

// The fitted vector: roughness, Specular IOR Level, Diffuse Roughness, sheen weight and roughness, and with a coat
// the coat's roughness.
int fitted_count(const CyclesPrincipledFitSettings& settings) { return settings.coat ? 6 : 5; }

CyclesPrincipledParameters with_shape(const Eigen::VectorXd& x, const CyclesPrincipledFitSettings& settings) {
  CyclesPrincipledParameters p;
  p.ior = settings.ior;
  p.roughness = x(0);
  p.specular_ior_level = x(1);
  p.diffuse_roughness = x(2);
  p.sheen_weight = x(3);
  p.sheen_roughness = x(4);
  p.coat_weight = settings.coat ? 1.0 : 0.0;
  p.coat_ior = settings.coat_ior;
  p.coat_roughness = settings.coat ? x(5) : p.coat_roughness;
  return p;
}

// The colour that gives the target albedo at normal incidence (color_for_albedo), and what the albedo misses where
// [0, 1] holds no such colour.
CyclesPrincipled with_solved_color(const CyclesPrincipled& surface, const Rgb& target, Rgb& miss) {
  const Rgb color = color_for_albedo(
      [&](const Rgb& diffuse) { return surface.albedo_with_diffuse_color(1.0, diffuse); }, target, miss);
  return surface.with_base_color(color);
}

CyclesPrincipled solved_surface(const Eigen::VectorXd& x, const CyclesPrincipledFitSettings& settings,
                                const Rgb& target, Rgb& miss) {
  return with_solved_color(CyclesPrincipled(with_shape(x, settings)), target, miss);
}

}  // namespace

CyclesPrincipledFit fit_cycles_principled(const BrdfFitTarget& target, const CyclesPrincipledFitSettings& settings) {
  const int fitted = fitted_count(settings);
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(fitted), hi = Eigen::VectorXd::Ones(fitted);
  lo(0) = lo(4) = kMinFittedRoughness;
  if (settings.coat) lo(5) = kMinFittedRoughness;
  // A glossy start and a matte one.
  const Eigen::VectorXd starts[] = {(Eigen::VectorXd(6) << 0.4, 0.5, 0.0, 0.0, 0.5, 0.3).finished().head(fitted),
                                    (Eigen::VectorXd(6) << 0.8, 0.3, 0.5, 0.3, 0.5, 0.3).finished().head(fitted)};
  const auto found = fit_surface(
      target,
      [&](const Eigen::VectorXd& x, Rgb& miss) { return solved_surface(x, settings, target.albedo.front(), miss); },
      starts, lo, hi);
  return {found.surface.parameters(), found.albedo_matched, found.albedo_miss, found.errors};
}

}  // namespace skinlayer
