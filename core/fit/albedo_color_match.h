// "Pick the colour, get the parameters" for a layered material (issue 25): the top layer's single-scattering
// albedo per channel such that the reflectance (surface and subsurface) at normal incidence is the target channel.
// That reflectance rises monotonically with Omega, so each channel is a bisection on [0, 1]; a target out of reach
// ends at Omega = 0 or 1, the nearest the channel can come.
#pragma once

#include <array>

#include "core/material.h"
#include "core/solve/solve_options.h"

namespace skinlayer {

struct AlbedoColorMatch {
  std::array<double, 3> albedo{};       // the top layer's Omega per channel
  std::array<double, 3> reflectance{};  // what each channel then reflects at normal incidence
  int solves = 0;
};

// channels[c]: channel c's material (its other layers' albedos are that channel's); its top albedo is replaced.
// `options` pass the caller's cache (an own one when none is given: every bisection step reuses the interface
// operators, which do not depend on the albedo), parallel-for and cancellation check to the solves.
AlbedoColorMatch match_top_albedo(const std::array<Material, 3>& channels, const std::array<double, 3>& target,
                                  const SolveOptions& options = {});

}  // namespace skinlayer
