// A material document's directional-hemispherical energy fractions (core/solver.h's DirectionalAlbedo) per colour
// channel: what `skinlayer albedo` writes and the Python module's Solution.albedo returns, through the same code.
// Always the layer model's (stam): the comparison models have no albedo solve of their own.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "app/material/material_document.h"
#include "core/parallel_for.h"
#include "core/solver.h"

namespace skinlayer {

// One row list per channel, each row one of theta_i (radians, in order): a grey document has one channel, a colour
// document (RGB, or a skin's spectrum mixed into linear sRGB under D65) three, red, green, blue. An RGB document's
// distinct channels are solved together; a skin's wavelengths one after another through one interface cache.
// Throws ParameterError for a material out of range and SolveCancelled when `cancelled` returns true.
std::vector<std::vector<DirectionalAlbedo>> document_albedo(const MaterialDocument& document,
                                                            std::span<const double> thetas_radians,
                                                            const ParallelFor& parallel_for,
                                                            const std::function<bool()>& cancelled = {});

}  // namespace skinlayer
