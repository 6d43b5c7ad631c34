// glTF 2.0's material fitted to samples of a BRDF, its albedo at normal incidence matched.
#include "core/fit/gltf_fit.h"

#include <cmath>

#include "core/fit/surface_fit.h"

namespace skinlayer {
namespace {

// The fitted vector: roughness, specular, sheen strength and roughness, and with a clearcoat its roughness.
int fitted_count(const GltfFitSettings& settings) { return settings.clearcoat ? 5 : 4; }

GltfPbrParameters with_shape(const Eigen::VectorXd& x, const GltfFitSettings& settings) {
  GltfPbrParameters p;
  p.metallic = 0.0;
  p.ior = settings.ior;
  p.roughness = x(0);
  p.specular = x(1);
  p.sheen_color = Rgb::Constant(x(2));
  p.sheen_roughness = x(3);
  p.clearcoat = settings.clearcoat ? 1.0 : 0.0;
  p.clearcoat_roughness = settings.clearcoat ? x(4) : 0.0;
  return p;
}

// The base colour that gives the target albedo at normal incidence: the albedo is a + b base per channel, b > 0
// (the diffuse lobe's weight), so base = (target - a) / b, held in [0, 1]; what the albedo then misses goes to `miss`.
GltfPbr with_solved_color(const GltfPbr& surface, const Rgb& target, Rgb& miss) {
  const Rgb dark = surface.albedo_with_diffuse_color(1.0, Rgb::Zero());
  const Rgb slope = surface.albedo_with_diffuse_color(1.0, Rgb::Ones()) - dark;
  const Rgb color = ((target - dark) / slope.max(1e-300)).max(0.0).min(1.0);
  const Rgb off = surface.albedo_with_diffuse_color(1.0, color) - target;
  miss = ((target > dark) && (target < dark + slope)).select(Rgb::Zero(), off);
  return surface.with_base_color(color);
}

GltfPbr solved_surface(const Eigen::VectorXd& x, const GltfFitSettings& settings, const Rgb& target, Rgb& miss) {
  return with_solved_color(GltfPbr(with_shape(x, settings)), target, miss);
}

}  // namespace

GltfFit fit_gltf(const BrdfFitTarget& target, const GltfFitSettings& settings) {
  const int fitted = fitted_count(settings);
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(fitted), hi = Eigen::VectorXd::Ones(fitted);
  lo(0) = kMinFittedRoughness;
  lo(3) = kMinFittedSheenRoughness;
  if (settings.clearcoat) lo(4) = kMinFittedRoughness;
  // A glossy start and a matte one.
  const Eigen::VectorXd starts[] = {(Eigen::VectorXd(5) << 0.4, 1.0, 0.0, 0.5, 0.3).finished().head(fitted),
                                    (Eigen::VectorXd(5) << 0.8, 0.5, 0.3, 0.5, 0.3).finished().head(fitted)};
  const auto found = fit_surface(
      target,
      [&](const Eigen::VectorXd& x, Rgb& miss) { return solved_surface(x, settings, target.albedo.front(), miss); },
      starts, lo, hi);
  GltfFit fit{found.surface.parameters(), found.albedo_matched, found.albedo_miss, found.errors};
  if (fit.parameters.sheen_color.maxCoeff() == 0.0) fit.parameters.sheen_roughness = 0.0;  // no sheen: its default
  return fit;
}

}  // namespace skinlayer
