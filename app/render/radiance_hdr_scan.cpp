#include "app/render/radiance_hdr_scan.h"

#include <cstddef>

namespace skinlayer {
namespace {

std::string truncated(std::size_t j) { return "truncated in scanline " + std::to_string(j); }

}  // namespace

std::optional<std::string> radiance_pixel_data_problem(std::string_view bytes, int width, int height) {
  const std::size_t header_end = bytes.find("\n\n");
  if (header_end == std::string_view::npos) return "truncated in the header (no empty line ends it)";
  const std::size_t resolution_end = bytes.find('\n', header_end + 2);
  if (resolution_end == std::string_view::npos) return "truncated after the header (no resolution line)";
  std::size_t at = resolution_end + 1;
  const auto w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
  const auto left = [&] { return bytes.size() - at; };
  const auto byte = [&](std::size_t n) { return static_cast<unsigned char>(bytes[n]); };
  const auto flat_from = [&](std::size_t pixels_left) -> std::optional<std::string> {
    if (left() / 4 < pixels_left)
      return "truncated (" + std::to_string(left()) + " bytes of pixels left for " + std::to_string(pixels_left) +
             " pixels)";
    return std::nullopt;
  };
  if (w < 8 || w >= 32768) return flat_from(w * h);
  for (std::size_t j = 0; j < h; ++j) {
    if (left() < 4) return truncated(j);
    if (byte(at) != 2 || byte(at + 1) != 2 || (byte(at + 2) & 0x80) != 0) return flat_from(w * (h - j));
    if ((static_cast<std::size_t>(byte(at + 2)) << 8 | byte(at + 3)) != w) {
      return "bad run-length data in scanline " + std::to_string(j) + " (its length is not the image's width)";
    }
    at += 4;
    for (int channel = 0; channel < 4; ++channel) {
      for (std::size_t i = 0; i < w;) {
        if (left() < 1) return truncated(j);
        std::size_t count = byte(at++);
        const bool run = count > 128;
        if (run) count -= 128;
        if (count == 0 || count > w - i) {
          return "bad run-length data in scanline " + std::to_string(j) + " (a run of " + std::to_string(count) +
                 " pixels where " + std::to_string(w - i) + " are left)";
        }
        const std::size_t values = run ? 1 : count;
        if (left() < values) return truncated(j);
        at += values;
        i += count;
      }
    }
  }
  return std::nullopt;
}

}  // namespace skinlayer
