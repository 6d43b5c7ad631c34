// A walk over a Radiance .hdr file's pixel data before stb_image decodes it. stb_image reads past the end of its
// input as zeros, and its run-length decoder loops for ever on a run of length 0 (which a zero past the end also
// is), so a truncated or damaged file can hang it or come out partly black. The walk follows the decoder's steps
// without decoding:
//   * the header ends at its first empty line, the resolution line ("-Y H +X W") after it, then the pixels;
//   * scanlines from 8 to 32767 pixels wide may be run-length coded: a marker 2, 2, W >> 8, W & 255, then per
//     channel (R, G, B, E in turn) runs that fill the W pixels: a count byte c > 128 and one value (c - 128
//     pixels), or 0 < c <= 128 and c values;
//   * any other scanline (and a marker that is not 2, 2 with the high bit of the third byte clear) starts flat
//     data: 4 bytes a pixel for every pixel left (the marker's 4 bytes are the first pixel).
// (Greg Ward, "Real Pixels", Graphics Gems II, 1991; the file format of Radiance.)
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace skinlayer {

// Why stb_image could not decode width x height pixels of `bytes` to the end ("truncated: ...", "bad run-length
// data in scanline J"), or nullopt where it can. width and height are the header's (stbi_info).
std::optional<std::string> radiance_pixel_data_problem(std::string_view bytes, int width, int height);

}  // namespace skinlayer
