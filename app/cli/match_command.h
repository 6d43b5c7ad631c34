// `skinlayer match`: pick the colour, get the parameters; or fit a measured spectrum (issue 25).
//   match --color R,G,B|#RRGGBB [--linear] [material flags | --skin ...] [-o FILE.json]
//   match --spectrum FILE.csv [--theta-i DEG] [--range FROM:TO] [material flags] [-o FILE.json]
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string match_usage();

// Runs the command on arguments (after "match") and returns the exit status. Errors are thrown (see errors.h).
int run_match_command(std::span<const std::string_view> arguments, std::ostream& out, std::ostream& err);

}  // namespace skinlayer::cli
