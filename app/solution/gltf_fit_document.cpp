#include "app/solution/gltf_fit_document.h"

#include <algorithm>

namespace skinlayer {

GltfFitSettings gltf_fit_settings(const MaterialDocument& document) {
  const OpenPbrFitSettings interfaces = openpbr_fit_settings(document);
  GltfFitSettings settings;
  // Under a coat the base's interface is the coat's over the base's: glTF's base reflects by its ior against
  // whatever is above without reducing it (Appendix B, KHR_materials_clearcoat), so it takes the relative index.
  const double ior = interfaces.coat ? interfaces.specular_ior / interfaces.coat_ior : interfaces.specular_ior;
  // glTF's ior is >= 1; Schlick's F0 = ((n - 1) / (n + 1))^2 is the same for n and 1 / n.
  settings.ior = std::max(ior, 1.0 / ior);
  settings.clearcoat = interfaces.coat;
  return settings;
}

double gltf_fit_top_ior(const MaterialDocument& document) { return document.layer.eta; }

DocumentFit<GltfFit> fit_gltf(const MaterialDocument& document, const ParallelFor& parallel_for) {
  return {fit_gltf(brdf_fit_target(document, parallel_for), gltf_fit_settings(document)),
          "none: the glTF export carries no subsurface radius (KHR_materials_volume and "
          "KHR_materials_diffuse_transmission are not built)"};
}

FittedBrdfCosine fitted_brdf_cosine(const GltfFit& fit) {
  return
      [surface = GltfPbr(fit.parameters)](const Vec3& i, const Vec3& o) { return surface.brdf_cosine_weighted(i, o); };
}

}  // namespace skinlayer
