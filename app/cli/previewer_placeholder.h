// Stands in for the interactive previewer (`skinlayer` with no command) until the GLFW window exists.
#pragma once

#include <ostream>

namespace skinlayer::cli {

// Writes one line to err saying the previewer is not built yet and pointing to eval and albedo. Returns 2.
int run_previewer_placeholder(std::ostream& err);

}  // namespace skinlayer::cli
