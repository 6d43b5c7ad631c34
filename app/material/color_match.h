// "Pick the colour, get the parameters" on a material document (issue 25), for `skinlayer match --color` and the
// previewer's "Match colour..." picker alike: a skin's melanin, blood and scattering (core/fit/skin_fit.h), or
// otherwise the top layer's albedo per channel (core/fit/albedo_color_match.h), so that the reflectance at normal
// incidence (surface and subsurface, the sphere's centre under a white furnace) in linear sRGB is the target.
#pragma once

#include <Eigen/Core>

#include "app/material/material_document.h"
#include "core/parallel_for.h"

namespace skinlayer {

struct DocumentColorMatch {
  MaterialDocument document;  // the given document with the matched parameters
  Eigen::Vector3d reached;    // its colour, linear sRGB
  bool reachable = false;     // every channel within 0.5% of the target (a black one within 1e-4)
  double delta_e = 0.0;       // CIEDE2000 between the target and `reached`
};

// target: linear sRGB, each channel in [0, 1].
DocumentColorMatch match_document_color(MaterialDocument document, const Eigen::Vector3d& target,
                                        const ParallelFor& parallel_for = {});

}  // namespace skinlayer
