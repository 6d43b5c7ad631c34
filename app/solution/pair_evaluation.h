// A solved document evaluated over many direction pairs at once (the Python module's Solution.eval, which takes
// numpy arrays of a million pairs): the pairs are checked, then split into blocks that run through the caller's
// parallel-for, each pair through evaluate() (solved_document.h), so every value is the one `skinlayer eval` writes.
//
// Angles are degrees, as eval reads them: theta_i and theta_o in [0, 90] from the normal of their side, phi the
// outgoing minus the incident azimuth (180 = forward), any finite number. Values are BSDFs in 1/sr.
#pragma once

#include <functional>
#include <span>

#include "app/solution/solved_document.h"
#include "core/parallel_for.h"

namespace skinlayer {

// The channels a document's values have: 1 for a grey document, 3 (red, green, blue) otherwise.
int value_channels(const SolvedDocument& solved);

// Throws ParameterError for the first pair out of range, naming the array and the index:
// "theta_o[12] = 95 is out of range; valid range is [0, 90] (degrees)"; also for arrays of unequal length.
void check_direction_pairs(std::span<const double> theta_i, std::span<const double> theta_o,
                           std::span<const double> phi);

// Where the values go: n = theta_i.size() entries of surface, n x value_channels entries (pair-major) of the others.
struct BsdfArrays {
  std::span<double> surface;     // brdf_surface: no albedo in it, one value per pair
  std::span<double> subsurface;  // brdf_subsurface
  std::span<double> brdf;        // brdf_surface + brdf_subsurface
  std::span<double> btdf;        // btdf, without the unscattered beam
};

// Fills `out` for every pair (checked first), in the order of the pairs' table cells (for the memory caches; the
// values do not depend on it). At most 2^32 - 1 pairs at once. Asks `cancelled` between blocks: when it returns
// true the remaining blocks are skipped and SolveCancelled is thrown.
void evaluate_pairs(const SolvedDocument& solved, std::span<const double> theta_i, std::span<const double> theta_o,
                    std::span<const double> phi, const BsdfArrays& out, const ParallelFor& parallel_for,
                    const std::function<bool()>& cancelled = {});

}  // namespace skinlayer
