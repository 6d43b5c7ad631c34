// skinlayer render [material flags] [--albedo A | r,g,b] [--light-theta D] [--light-phi D] [--view sphere|polar|both]
//                  [--size WxH] [--exposure E] [--log] -o out.png
// Renders the previewer's picture offscreen through OSMesa, with the same renderer as the window, and writes a PNG.
#pragma once

#include <ostream>
#include <span>
#include <string_view>

namespace skinlayer::cli {

int run_render_command(std::span<const std::string_view> arguments, std::ostream& out, std::ostream& progress);
std::string render_usage();

}  // namespace skinlayer::cli
