#include "app/solution/shader_fit.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "app/solution/document_albedo.h"
#include "app/solution/pair_evaluation.h"
#include "app/solution/solved_document.h"
#include "app/solution/subsurface_radius.h"
#include "core/conventions.h"

namespace skinlayer {

BrdfFitTarget brdf_fit_target(const MaterialDocument& document, const ParallelFor& parallel_for) {
  BrdfFitTarget target;
  target.pairs = fit_pairs();
  std::vector<double> theta_i, theta_o, phi;
  for (const DirectionPair& pair : target.pairs) {
    theta_i.push_back(radians_to_degrees(std::acos(pair.omega_i.z())));
    theta_o.push_back(radians_to_degrees(std::acos(pair.omega_o.z())));
    phi.push_back(radians_to_degrees(std::atan2(pair.omega_o.y(), pair.omega_o.x())));  // the light is at azimuth 0
  }
  const SolvedDocument solved = solve_document(document, SubsurfaceModel::Stam, parallel_for);
  const std::size_t n = target.pairs.size(), width = static_cast<std::size_t>(value_channels(solved));
  std::vector<double> surface(n), subsurface(n * width), brdf(n * width), btdf(n * width);
  evaluate_pairs(solved, theta_i, theta_o, phi, {surface, subsurface, brdf, btdf}, parallel_for);
  for (std::size_t k = 0; k < n; ++k) {
    Rgb value;
    for (int c = 0; c < 3; ++c) value(c) = brdf[k * width + (width == 1 ? 0 : static_cast<std::size_t>(c))];
    target.brdf_cosine.push_back(value * target.pairs[k].omega_i.z());
  }
  for (int degrees = 0; degrees <= 80; degrees += 20) target.albedo_angles.push_back(degrees_to_radians(degrees));
  const std::vector<std::vector<DirectionalAlbedo>> albedo =
      document_albedo(document, target.albedo_angles, parallel_for);
  for (std::size_t a = 0; a < target.albedo_angles.size(); ++a) {
    Rgb value;
    for (int c = 0; c < 3; ++c)
      value(c) = albedo[albedo.size() == 1 ? 0 : static_cast<std::size_t>(c)][a].reflectance();
    target.albedo.push_back(value);
  }
  return target;
}

DocumentFit<PrincipledFit> fit_principled(const MaterialDocument& document, const ParallelFor& parallel_for) {
  DocumentFit<PrincipledFit> result{fit_principled(brdf_fit_target(document, parallel_for)), ""};
  const SubsurfaceScattering scattering = subsurface_scattering(document);
  result.radius_source = scattering.source;
  PrincipledParameters& p = result.fit.parameters;
  p.ior = document.layer.eta;  // for transmission, which the fit leaves at 0: the layer's own index if raised
  p.subsurface_color = p.base_color;
  if (scattering.mean_free_path_mm) {
    // One anisotropy for the three channels (the node's input is a number), within Cycles' clamp; the radius is
    // then the reduced mean free path that gives the material's extinction, in metres.
    p.subsurface_anisotropy = std::clamp(scattering.anisotropy.mean(), 0.0, 0.9);
    p.subsurface_radius = *scattering.mean_free_path_mm / (1.0 - p.subsurface_anisotropy) / 1000.0;
  }
  return result;
}

OpenPbrFitSettings openpbr_fit_settings(const MaterialDocument& document) {
  const Material& m = document.layer;
  OpenPbrFitSettings settings;
  settings.specular_ior = m.eta;
  const bool clear_top =
      !m.below.empty() && m.transparency() >= 0.9 && m.below.front().interface && m.below.front().interface->eta != 1.0;
  if (clear_top) {
    settings.coat = true;
    settings.coat_ior = m.eta;
    settings.specular_ior = m.eta * m.below.front().interface->eta;
  }
  return settings;
}

DocumentFit<OpenPbrFit> fit_openpbr(const MaterialDocument& document, const ParallelFor& parallel_for) {
  const SubsurfaceScattering scattering = subsurface_scattering(document);
  OpenPbrFitSettings settings = openpbr_fit_settings(document);
  settings.subsurface_weight = scattering.mean_free_path_mm ? 1.0 : 0.0;
  DocumentFit<OpenPbrFit> result{fit_openpbr(brdf_fit_target(document, parallel_for), settings), scattering.source};
  if (scattering.mean_free_path_mm) {
    OpenPbrParameters& p = result.fit.parameters;
    p.subsurface_radius = scattering.mean_free_path_mm->maxCoeff();
    p.subsurface_radius_scale = *scattering.mean_free_path_mm / p.subsurface_radius;
    p.subsurface_scatter_anisotropy = std::clamp(scattering.anisotropy.mean(), -1.0, 1.0);
  }
  return result;
}

}  // namespace skinlayer
