// PNG through libpng (libpng-dev): 8-bit RGBA pictures with international text chunks (iTXt), encoded to and
// decoded from memory. The pictures skinlayer writes carry their material in one (picture_metadata.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skinlayer {

struct PngText {
  std::string keyword;  // 1-79 Latin-1 characters
  std::string text;     // UTF-8, stored uncompressed
};

// The PNG file's bytes for width x height RGBA8 pixels (top row first) and the text chunks, written before the
// image data. Throws std::runtime_error with libpng's reason for an invalid image or keyword.
std::string encode_png_rgba8(int width, int height, const std::vector<std::uint8_t>& rgba,
                             const std::vector<PngText>& texts = {});

// True when the bytes start with the PNG signature.
bool is_png(std::string_view bytes);

// The text of the first tEXt, zTXt or iTXt chunk before the image data with this keyword, or nullopt when there is
// none. Throws std::runtime_error with libpng's reason for a damaged PNG.
std::optional<std::string> read_png_text(std::string_view bytes, std::string_view keyword);

}  // namespace skinlayer
