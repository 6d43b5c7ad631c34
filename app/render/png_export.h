// PNG export of RGBA8 pixels (stb_image_write from libstb-dev).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace skinlayer {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // top row first
};

// Writes the image as PNG. Throws std::runtime_error naming the path if it cannot be written.
void write_png(const Image& image, const std::string& path);

// "skinlayer-YYYYMMDD-HHMMSS.png" in the current folder, from the local time.
std::string timestamped_png_name();

}  // namespace skinlayer
