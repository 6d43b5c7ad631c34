// PNG export of RGBA8 pixels through libpng (app/material/png_codec.h), written atomically, with optional text
// chunks (the picture's material: app/material/picture_metadata.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/material/png_codec.h"

namespace skinlayer {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // top row first
};

// Writes the image as PNG with the text chunks; either the whole file is written or none (the target is left as
// it was). Throws std::runtime_error naming the path if it cannot be written.
void write_png(const Image& image, const std::string& path, const std::vector<PngText>& texts = {});

// "skinlayer-YYYYMMDD-HHMMSS.png" in the current folder, from the local time.
std::string timestamped_png_name();

}  // namespace skinlayer
