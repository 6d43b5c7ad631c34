// A material document fitted with a renderer's shader (docs/model.md §22.2, §22.4): the samples of its BRDF that the
// fits need, taken through the same solve as `skinlayer eval` and `skinlayer albedo`, and the fits, with the
// subsurface scattering the BRDF does not show (app/solution/subsurface_scattering.h). One path for `skinlayer fit`,
// `skinlayer export --format blender|mtlx` and the previewer's buttons. The fits are of the layer model (Stam's),
// whatever model the document names.
#pragma once

#include <functional>
#include <string>

#include "app/material/material_document.h"
#include "core/fit/openpbr_fit.h"
#include "core/fit/principled_fit.h"
#include "core/parallel_for.h"

namespace skinlayer {

// The document's BRDF (surface and subsurface), cosine-weighted, on fit_pairs(), and its directional albedo at 0,
// 20, 40, 60 and 80 degrees, in linear sRGB (a skin's spectrum through app/material/color_channels.h). Throws
// ParameterError for a material out of range.
BrdfFitTarget brdf_fit_target(const MaterialDocument& document, const ParallelFor& parallel_for);

// A fit, and what its subsurface radius was taken from (or why it has none).
template <typename Fit>
struct DocumentFit {
  Fit fit;
  std::string radius_source;
};

// The Principled fit. Its subsurface colour is the base colour; where the material has a length, its anisotropy the
// layer's g (one number, in [0, 0.9]) and its radius the reduced mean free path 1 / ((1 - g) mu_t) in metres
// (Blender's unit), which Cycles' random walk reads back as the material's extinction. The subsurface weight stays
// 0, as fitted (the random walk at weight 1 renders 2-5% brighter than the fitted BRDF, measured: the artist's
// choice).
DocumentFit<PrincipledFit> fit_principled(const MaterialDocument& document, const ParallelFor& parallel_for);

// The interfaces the OpenPBR fit keeps from the document: without a coat the top's index is specular_ior; a stack
// whose first layer is clear (it lets through 90% or more of normal light, T >= 0.9) over a refracting interface has
// a coat of the top's index, and specular_ior is the index under it.
OpenPbrFitSettings openpbr_fit_settings(const MaterialDocument& document);

// The OpenPBR fit. Where the material has a mean free path, subsurface_weight is 1 (the same BRDF, and translucency
// in a renderer that scatters under the surface), subsurface_radius its largest channel in millimetres,
// subsurface_radius_scale the channels over it and subsurface_scatter_anisotropy the layer's g.
DocumentFit<OpenPbrFit> fit_openpbr(const MaterialDocument& document, const ParallelFor& parallel_for);

// A fit's shader as a BRDF, f cos(theta_i) for light omega_i seen from omega_o: what the fit's picture draws and the
// previewer tabulates.
using FittedBrdfCosine = std::function<Rgb(const Vec3& omega_i, const Vec3& omega_o)>;
FittedBrdfCosine fitted_brdf_cosine(const PrincipledFit& fit);
FittedBrdfCosine fitted_brdf_cosine(const OpenPbrFit& fit);

}  // namespace skinlayer
