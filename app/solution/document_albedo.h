// A material document's directional-hemispherical energy fractions (core/solver.h's DirectionalAlbedo) per colour
// channel: what `skinlayer albedo` writes and the Python module's Solution.albedo returns, through the same code.
// Always the layer model's (stam): the comparison models have no albedo solve of their own.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <span>
#include <vector>

#include "app/material/material_document.h"
#include "core/parallel_for.h"
#include "core/solver.h"

namespace skinlayer {

// One row list per channel, each row one of theta_i (radians, in order): a grey document has one channel, a colour
// document (RGB, or a skin's spectrum mixed into linear sRGB under D65) three, red, green, blue. An RGB document's
// distinct channels are solved together; a skin's wavelengths side by side, each chunk with a copy of a warm
// interface cache (core/solve/batch_solve.h: for_each_with_warm_cache). `options` carry the caller's cache,
// parallel-for, cancellation check and preview. Throws ParameterError for a material out of range and SolveCancelled
// when the check says stop.
std::vector<std::vector<DirectionalAlbedo>> document_albedo(const MaterialDocument& document,
                                                            std::span<const double> thetas_radians,
                                                            const SolveOptions& options);
// The same with the parallel-for and the cancellation check alone.
std::vector<std::vector<DirectionalAlbedo>> document_albedo(const MaterialDocument& document,
                                                            std::span<const double> thetas_radians,
                                                            const ParallelFor& parallel_for,
                                                            const std::function<bool()>& cancelled = {});

// The directional reflectance (surface and subsurface) at each of theta_i, in red, green and blue (a grey document's
// one channel in all three): document_albedo's reflectance() per row.
std::vector<Eigen::Array3d> document_reflectance_rgb(const MaterialDocument& document,
                                                     std::span<const double> thetas_radians,
                                                     const ParallelFor& parallel_for);

}  // namespace skinlayer
