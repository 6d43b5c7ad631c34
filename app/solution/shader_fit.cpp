#include "app/solution/shader_fit.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "app/solution/document_albedo.h"
#include "app/solution/pair_evaluation.h"
#include "app/solution/solved_document.h"
#include "app/solution/subsurface_scattering.h"
#include "core/conventions.h"

namespace skinlayer {

BrdfFitTarget brdf_fit_target(const MaterialDocument& document, const ParallelFor& parallel_for) {
  BrdfFitTarget target;
  target.pairs = fit_pairs();
  std::vector<Vec3> light, view;
  for (const DirectionPair& pair : target.pairs) {
    light.push_back(pair.omega_i);
    view.push_back(pair.omega_o);
  }
  const std::vector<Rgb> brdf =
      brdf_rgb(solve_document(document, SubsurfaceModel::Stam, parallel_for), light, view, parallel_for);
  for (std::size_t k = 0; k < brdf.size(); ++k) target.brdf_cosine.push_back(brdf[k] * light[k].z());
  for (int degrees = 0; degrees <= 80; degrees += 20) target.albedo_angles.push_back(degrees_to_radians(degrees));
  target.albedo = document_reflectance_rgb(document, target.albedo_angles, parallel_for);
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

FittedBrdfCosine fitted_brdf_cosine(const PrincipledFit& fit) {
  return [p = fit.parameters](const Vec3& i, const Vec3& o) { return principled_brdf_cosine_weighted(p, i, o); };
}

FittedBrdfCosine fitted_brdf_cosine(const OpenPbrFit& fit) {
  return [surface = OpenPbrSurface(fit.parameters)](const Vec3& i, const Vec3& o) {
    return surface.brdf_cosine_weighted(i, o);
  };
}

}  // namespace skinlayer
