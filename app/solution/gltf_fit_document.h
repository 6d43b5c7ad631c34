// A material document fitted with glTF 2.0's material (core/fit/gltf_fit.h): the same samples of its BRDF as the
// other shader fits (app/solution/shader_fit.h: brdf_fit_target), and the interfaces kept from the document as the
// OpenPBR fit keeps them. The path for `skinlayer fit --target gltf` and `skinlayer export --format gltf`.
#pragma once

#include "app/material/material_document.h"
#include "app/solution/shader_fit.h"
#include "core/fit/gltf_fit.h"
#include "core/parallel_for.h"

namespace skinlayer {

// The interfaces the glTF fit keeps: without a clear top the top's index is KHR_materials_ior's ior; a stack whose
// first layer is clear over a refracting interface (openpbr_fit_settings' test) has clearcoat 1 and as ior the
// interface's relative index under it (glTF's base reflects against what is above it, unreduced by a coat).
// KHR_materials_clearcoat's coat is of index 1.5 whatever the top's is (gltf_fit_top_ior gives the top's).
GltfFitSettings gltf_fit_settings(const MaterialDocument& document);

// The material's top index: what a clearcoat would need and glTF cannot take (1.5 is fixed).
double gltf_fit_top_ior(const MaterialDocument& document);

// The fit. glTF 2.0 has no subsurface radius among the extensions built (KHR_materials_volume and
// _diffuse_transmission are not), so radius_source says so.
DocumentFit<GltfFit> fit_gltf(const MaterialDocument& document, const ParallelFor& parallel_for);

// The fitted material as a BRDF, f cos(theta_i) for light omega_i seen from omega_o.
FittedBrdfCosine fitted_brdf_cosine(const GltfFit& fit);

}  // namespace skinlayer
