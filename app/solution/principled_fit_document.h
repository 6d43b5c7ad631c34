// A material document fitted with the Principled BSDF of Blender 4.x and 5.x (core/fit/cycles_principled_fit.h): the
// same samples of its BRDF as the other shader fits (app/solution/shader_fit.h: brdf_fit_target), with the
// interfaces kept from the document as the OpenPBR fit keeps them. The path for `skinlayer fit --target principled`,
// `skinlayer export --format blender` and the previewer's "B: Principled fit".
#pragma once

#include "app/material/material_document.h"
#include "app/solution/shader_fit.h"
#include "core/fit/cycles_principled_fit.h"
#include "core/parallel_for.h"

namespace skinlayer {

// The interfaces the fit keeps (openpbr_fit_settings' test): IOR is the top's index, or under a clear first layer
// the index below it, with a coat of the top's index; each held in the node's range (IOR [1, 1000], Coat IOR [1, 4]).
CyclesPrincipledFitSettings cycles_principled_fit_settings(const MaterialDocument& document);

// The fit. Where the material has a length, the subsurface is set as Cycles' random walk reads it (4.x as 3.4:
// integrator/subsurface_random_walk.h): Subsurface Anisotropy the layer's g (one number, in [0, 0.9]), Subsurface
// Scale the largest channel's reduced mean free path 1 / ((1 - g) mu_t) in metres (Blender's unit) and Subsurface
// Radius the channels over it (Subsurface IOR, which only the "Random Walk (Skin)" method shows, stays). The weight
// stays 0, as fitted: at the BRDF's scale Cycles' subsurface is a Lambert lobe, not the fitted diffuse.
DocumentFit<CyclesPrincipledFit> fit_cycles_principled(const MaterialDocument& document,
                                                       const ParallelFor& parallel_for);

// The fitted node as a BRDF, f cos(theta_i) for light omega_i seen from omega_o.
FittedBrdfCosine fitted_brdf_cosine(const CyclesPrincipledFit& fit);

}  // namespace skinlayer
