// The skin's directional albedos across wavelengths: one layered solve per wavelength (skin_optics.h). The
// interfaces do not depend on the wavelength (eta is not dispersive), so every wavelength after the first re-solves
// with the interface operators cached (core/solve/solve_cache.h).
#pragma once

#include <span>
#include <vector>

#include "core/skin/skin_optics.h"
#include "core/solver.h"

namespace skinlayer {

// One row list per wavelength (in order), one row per theta_i (radians), as directional_albedo. options.cache is
// used when given (and warmed), else a cache lives for this call; with options.parallel_for the wavelengths after
// the first run side by side, in chunks with copies of the warm cache.
std::vector<std::vector<DirectionalAlbedo>> skin_directional_albedo(const SkinParameters& skin,
                                                                    const Material& interfaces,
                                                                    std::span<const double> wavelengths_nm,
                                                                    std::span<const double> theta_i,
                                                                    const SolveOptions& options = {});

}  // namespace skinlayer
