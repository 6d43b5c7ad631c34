// `skinlayer profile [material flags] [--incidence normal] [--annuli DR:N | --radii LIST]`: where a pencil beam's
// light leaves the layer (the spatial profile, docs/model.md §21).
//
// Writes, per annulus, r_inner_U,r_outer_U,reflectance,transmittance (the mean over it), or per radius
// r_U,reflectance,transmittance (the value there): the scattered light leaving the top and the bottom per unit area
// and unit incident power, in 1/U^2. U is mm when the layer has its extinction (--mu-t), and mfp, the layer's mean
// free path, when it has none. An RGB albedo writes _r, _g and _b columns. What it cannot take yet (the command's
// help lists it) is one line saying so.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string profile_usage();

// Runs the command on arguments (after "profile") and returns the exit status. Errors are thrown (see errors.h).
// Progress lines (a skin's wavelengths done) go to `progress`.
int run_profile_command(std::span<const std::string_view> arguments, std::ostream& out, std::ostream& progress);

}  // namespace skinlayer::cli
