// The light a rough dielectric interface scatters more than once on its microsurface: its BSDF at chosen exit
// directions, estimated from the microsurface random walk (core/reference/microsurface_walk.h) by next-event
// estimation. At every meeting after the first the walk adds the density with which the light leaves from there
// toward each exit direction and meets the microsurface no more,
//   q(o) = p(w -> o) C1^Lambda(o)          (leaving on the meeting's side)
//   q(o) = p(w -> o) (1 - C1)^Lambda(-o)   (leaving beyond it),
// p the density of one meeting (MicrosurfaceScatterDensity). Averaged over walks, q(o) is the multiply scattered
// BSDF times |cos theta_o|, so each exit direction gets a value of its own, not an average over a bin. The BSDF is
// even in azimuth, so each direction's estimate is the mean of those at +phi and -phi.
//
// Angles: graphics convention (core/conventions.h). The light comes from wi = (sin theta_i, 0, +-cos theta_i) (the
// sign is the side it arrives from) and leaves at (theta_o, phi), phi = phi_o - phi_i: phi = pi is forward, on the
// light's own side ("back", reflection) and beyond it (transmission). Values in 1/sr, not cosine-weighted.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

struct MultipleScatteringEstimateOptions {
  long walks_with_meetings = 10'000;  // stop once this many walks have met the microsurface twice or more,
  long max_walks = 400'000;           // or after this many walks in all,
  long min_walks = 20'000;            // but never before this many
  std::uint64_t seed = 1;
};

struct MultipleScatteringEstimate {
  std::vector<double> exit_thetas, exit_phis;  // radians
  long walks = 0;
  long walks_with_meetings = 0;   // walks that met the microsurface two or more times
  std::vector<double> values[2];  // side s (0 back, 1 beyond): [theta index * phis + phi index], 1/sr

  double at(int side, std::size_t theta, std::size_t phi) const { return values[side][theta * exit_phis.size() + phi]; }
};

// The estimate for light arriving at polar angle theta_i (radians) from above (from_above) or below, at every pair
// of exit_thetas and exit_phis (radians), on both sides.
MultipleScatteringEstimate estimate_multiple_scattering(const RoughDielectric& interface, double theta_i,
                                                        bool from_above, std::span<const double> exit_thetas,
                                                        std::span<const double> exit_phis,
                                                        const MultipleScatteringEstimateOptions& options);

}  // namespace skinlayer
