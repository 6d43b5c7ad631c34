// The picture of one validation set: the solver's BSDF as curves, its bin averages as level bars, and the Monte
// Carlo bin estimates as points with +-2 standard-error bars; reflection above, transmission (when the layer
// transmits) below; the plane of incidence on the left (back, phi = 0, at negative angles; forward, phi = 180
// degrees, at positive ones) and the plane across it (phi = 90 degrees) on the right.
#pragma once

#include "app/figures/font.h"
#include "app/render/png_export.h"
#include "app/validate/validation_run.h"

namespace skinlayer::validation {

Image draw_validation_plot(const SetResult& result, const figures::Font& font);

}  // namespace skinlayer::validation
