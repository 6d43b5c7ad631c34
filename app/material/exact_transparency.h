// The transparency T = exp(-tau) written with the fewest significant digits that read back to exactly the same
// optical depth (0.1, not exp(-(-ln 0.1)) = 0.10000000000000002), for the command line and material files.
#pragma once

#include <optional>

namespace skinlayer {

// The shortest T (at most 17 digits) with optical_depth_from_transparency(T) == tau, or nullopt when none is
// (then tau itself must be written). tau = +infinity gives 0.
std::optional<double> exact_transparency(double tau);

}  // namespace skinlayer
