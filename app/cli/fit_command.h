// `skinlayer fit --target principled [material flags] [-o FILE]`: the parameters of Blender 3.4's Principled BSDF that
// best reproduce the material's BRDF (docs/model.md §22.2), with the fit's error, as JSON.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string fit_usage();

// Runs the command on arguments (after "fit") and returns the exit status. Errors are thrown (see errors.h).
int run_fit_command(std::span<const std::string_view> arguments, std::ostream& out);

}  // namespace skinlayer::cli
