#include "app/render/png_export.h"

#include <chrono>
#include <ctime>
#include <stdexcept>

#include "app/material/atomic_file.h"

namespace skinlayer {

void write_png(const Image& image, const std::string& path, const std::vector<PngText>& texts) {
  if (image.width < 1 || image.height < 1 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw std::runtime_error("cannot write " + path + ": the image is empty");
  }
  std::string bytes;
  try {
    bytes = encode_png_rgba8(image.width, image.height, image.rgba, texts);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("cannot write " + path + ": " + error.what());
  }
  write_file_atomically(path, bytes);
}

std::string timestamped_png_name() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm local{};
  localtime_r(&now, &local);
  char name[64];
  std::strftime(name, sizeof name, "skinlayer-%Y%m%d-%H%M%S.png", &local);
  return name;
}

}  // namespace skinlayer
