// `skinlayer albedo [material flags] [--theta-i LIST]`: directional-hemispherical energy fractions.
//
// Writes
//   theta_i,reflectance_surface,reflectance_subsurface,reflectance,transmittance,absorptance
// one row per incidence angle, in the order given: theta_i as parsed (degrees), then fractions of the incident
// flux; reflectance + transmittance + absorptance = 1. --theta-i is a comma-separated list of angles in [0, 90]
// degrees; omitted, it is 0,30,60,80.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string albedo_usage();

// Runs the command on arguments (after "albedo") and returns the exit status. Errors are thrown (see errors.h).
int run_albedo_command(std::span<const std::string_view> arguments, std::ostream& out);

}  // namespace skinlayer::cli
