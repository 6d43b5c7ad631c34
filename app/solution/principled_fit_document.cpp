#include "app/solution/principled_fit_document.h"

#include <algorithm>

#include "app/solution/subsurface_scattering.h"

namespace skinlayer {

CyclesPrincipledFitSettings cycles_principled_fit_settings(const MaterialDocument& document) {
  const OpenPbrFitSettings interfaces = openpbr_fit_settings(document);
  CyclesPrincipledFitSettings settings;
  settings.ior = std::clamp(interfaces.specular_ior, 1.0, 1000.0);
  settings.coat = interfaces.coat;
  settings.coat_ior = std::clamp(interfaces.coat_ior, 1.0, 4.0);
  return settings;
}

DocumentFit<CyclesPrincipledFit> fit_cycles_principled(const MaterialDocument& document,
                                                       const ParallelFor& parallel_for) {
  const SubsurfaceScattering scattering = subsurface_scattering(document);
  DocumentFit<CyclesPrincipledFit> result{
      fit_cycles_principled(brdf_fit_target(document, parallel_for), cycles_principled_fit_settings(document)),
      scattering.source};
  CyclesPrincipledParameters& p = result.fit.parameters;
  if (scattering.mean_free_path_mm) {
    p.subsurface_anisotropy = std::clamp(scattering.anisotropy.mean(), 0.0, 0.9);
    const Rgb reduced_metres = *scattering.mean_free_path_mm / (1.0 - p.subsurface_anisotropy) / 1000.0;
    p.subsurface_scale = reduced_metres.maxCoeff();
    p.subsurface_radius = reduced_metres / p.subsurface_scale;
  }
  return result;
}

FittedBrdfCosine fitted_brdf_cosine(const CyclesPrincipledFit& fit) {
  return [surface = CyclesPrincipled(fit.parameters)](const Vec3& i, const Vec3& o) {
    return surface.brdf_cosine_weighted(i, o);
  };
}

}  // namespace skinlayer
