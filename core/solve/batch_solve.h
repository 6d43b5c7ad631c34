// Many solves that share their interfaces (a spectrum: the same sigma and eta at every wavelength, only each layer's
// tau and Omega change), spread over the caller's parallel-for a whole solve at a time. The first material is solved
// alone, with the parallel-for inside it, which fills the cache with the interface operators and the phase
// projections; the rest run in chunks side by side, each chunk single-threaded with its own copy of that warm cache
// (the copies share the cached operators, which are immutable). On 2 cores this beats running one solve after
// another with the modes split across the cores, which a stack's short per-mode work keeps from scaling.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "core/solver.h"

namespace skinlayer {

// solve(materials[k], options) for every k, in order. options.cache is warmed and kept when given (an own cache
// otherwise); options.cancelled is asked by every solve.
std::vector<LayerTables> solve_batch(std::span<const Material> materials, const SolveOptions& options = {});

// The schedule above for any per-item work: body(0, options') first, with options' = options and its cache (or an own
// one), then body(k, chunk's options) for k = 1..count-1 in up to four chunks through options.parallel_for, each
// chunk single-threaded with its own copy of the warm cache. body(k, ...) runs once for every k.
void for_each_with_warm_cache(std::size_t count, const SolveOptions& options,
                              const std::function<void(std::size_t k, const SolveOptions& options)>& body);

}  // namespace skinlayer
