// The GLSL files of shaders/, embedded at build time (shaders/embed_text.cmake). Names are file names, e.g.
// "sphere.frag". Throws std::invalid_argument for an unknown name.
#pragma once

#include <string_view>

namespace skinlayer {

std::string_view shader_source(std::string_view name);

}  // namespace skinlayer
