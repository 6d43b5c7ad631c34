// How a solve is asked for (SolveOptions: table size, mode cap, the caller's cache, parallel-for and cancellation,
// the preview), the preview's caps, and the exception a cancelled solve throws. Declared apart from the solver's
// entry point (core/solver.h, which includes it) so that the resolution policy (core/solve/resolution.h) can read it.
#pragma once

#include <functional>

#include "core/cancellation.h"
#include "core/parallel_for.h"

namespace skinlayer {

class SolveCache;

struct SolveOptions {
  int table_size = 0;               // polar grid points on [0, pi/2] for the tables; 0 = default
  double fourier_tolerance = 1e-4;  // stop when two successive modes are below this fraction of mode 0's peak
  int max_modes = 0;                // hard cap on Fourier modes; 0 = automatic
  // true: the light that crosses the slab unscattered through the rough interfaces is evaluated exactly at the
  // requested directions (core/unscattered/unscattered_light.h) and the tables hold the rest; false: every path on the
  // discrete ordinates and the tables, as Stam 2001 publishes the method (for convergence studies and comparisons).
  bool exact_unscattered = true;
  // The caller's cache of interface operators (core/solve/solve_cache.h); null = build them for this solve only.
  SolveCache* cache = nullptr;
  // The caller's parallel-for (core/parallel_for.h). The solver runs independent work through it: RGB channels,
  // blocks of Fourier modes, the interface kernels; core itself starts no threads. Empty = one after another.
  ParallelFor parallel_for;
  // A quick look (the previewer's answer while a slider moves, before the full solve): the automatic resolution
  // capped at kPreviewResolution. Where that cap binds (sigma < 0.2, strong forward scattering, near-matched
  // interfaces) the energy fractions stay within 3% of the full solve's (mostly within 0.7%), since the interface
  // operators are matched to the accurate albedos at any N, but the lobes are smeared to the ordinates (pointwise
  // errors of a few percent, up to ~20% near peaks): docs/accuracy.md's figures hold for the full solve only.
  bool preview = false;
  // Asked while the interface operators are built (once per incident direction of each kernel) and between stages
  // (before each Fourier mode): returning true abandons the solve by throwing SolveCancelled (core/cancellation.h).
  // It may be called from the parallel-for's threads at once. Empty = never. A cancelled solve leaves nothing half
  // built in SolveOptions::cache.
  CancelCheck cancelled;
};

// What SolveOptions::preview caps the automatic resolution at: 15-18 ms for an RGB solve on both cores of the 2-core
// VM at the costliest corners of the parameter ranges (docs/benchmarks.md, BM_ResolveColorCorner), where the full
// resolution takes 0.2-1 s.
struct PreviewResolution {
  int ordinates = 32;
  int max_modes = 32;
  int interface_azimuths = 97;
};
inline constexpr PreviewResolution kPreviewResolution{};

}  // namespace skinlayer
