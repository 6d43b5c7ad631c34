#include "app/render/png_export.h"

#include <stb_image_write.h>  // libstb.so holds the implementation: do not define STB_IMAGE_WRITE_IMPLEMENTATION

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <stdexcept>

namespace skinlayer {

void write_png(const Image& image, const std::string& path) {
  if (image.width < 1 || image.height < 1 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw std::runtime_error("cannot write " + path + ": the image is empty");
  }
  errno = 0;
  if (stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4) == 0) {
    const std::string reason = errno != 0 ? std::strerror(errno) : "write failed";
    throw std::runtime_error("cannot write " + path + ": " + reason);
  }
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
