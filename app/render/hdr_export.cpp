#include "app/render/hdr_export.h"

#include <stb_image_write.h>  // libstb.so holds the implementation

#include <stdexcept>

namespace skinlayer {

std::string encode_hdr(int width, int height, const std::vector<float>& rgba) {
  std::vector<float> rgb(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t k = 0; k < rgb.size() / 3; ++k) {
    for (int c = 0; c < 3; ++c) rgb[3 * k + c] = rgba[4 * k + c];
  }
  std::string bytes;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  if (!stbi_write_hdr_to_func(append, &bytes, width, height, 3, rgb.data())) {
    throw std::runtime_error("cannot encode the .hdr picture");
  }
  return bytes;
}

}  // namespace skinlayer
