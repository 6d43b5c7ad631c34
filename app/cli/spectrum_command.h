// `skinlayer spectrum [material flags] [--skin ...] [--theta-i LIST] [--wavelength NM]`: directional-hemispherical
// reflectance, transmittance and absorptance per wavelength (issue 25).
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string spectrum_usage();

// Runs the command on arguments (after "spectrum") and returns the exit status. Errors are thrown (see errors.h).
int run_spectrum_command(std::span<const std::string_view> arguments, std::ostream& out);

}  // namespace skinlayer::cli
