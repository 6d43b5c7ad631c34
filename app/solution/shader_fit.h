// A material document fitted with a renderer's shader (docs/model.md §22.2): the samples of its BRDF that the fit
// needs, taken through the same solve as `skinlayer eval` and `skinlayer albedo`, and the fit. One path for
// `skinlayer fit`, `skinlayer export --format blender|mtlx` and the previewer's buttons.
#pragma once

#include "app/material/material_document.h"
#include "core/fit/principled_fit.h"
#include "core/parallel_for.h"

namespace skinlayer {

// The document's BRDF (surface and subsurface, Stam's model), cosine-weighted, on fit_pairs(), and its
// directional albedo at 0, 20, 40, 60 and 80 degrees, in linear sRGB (a skin's spectrum through
// app/material/color_channels.h). Throws ParameterError for a material out of range.
BrdfFitTarget principled_fit_target(const MaterialDocument& document, const ParallelFor& parallel_for);

// fit_principled(principled_fit_target(document)).
PrincipledFit fit_principled(const MaterialDocument& document, const ParallelFor& parallel_for);

}  // namespace skinlayer
