// Linear radiance pictures as Radiance .hdr (RGBE) files through stb_image_write (libstb-dev), for compositing and
// for tests: no tone map, no gamma.
#pragma once

#include <string>
#include <vector>

namespace skinlayer {

// The .hdr file's bytes for width x height RGBA float pixels (top row first; alpha is dropped).
std::string encode_hdr(int width, int height, const std::vector<float>& rgba);

}  // namespace skinlayer
