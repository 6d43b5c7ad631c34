// Fuzz target: a Radiance .hdr environment (app/render/environment_map.h, stb_image underneath). A map that reads is
// equirectangular, within the size limit, and every texel finite and >= 0.
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "app/render/environment_map.h"
#include "tests/fuzz/fuzz_target.h"

using namespace skinlayer;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  EnvironmentMap map;
  if (fuzz::refused_cleanly<std::runtime_error>(
          [&] { map = decode_hdr_environment(fuzz::input_bytes(data, size), "fuzz.hdr"); })) {
    return 0;
  }
  fuzz::require(map.width >= 1 && map.height >= 1 && std::abs(map.width - 2 * map.height) <= 1 &&
                    map.width <= kMaxEnvironmentWidth,
                "a map read with a size out of bounds");
  fuzz::require(map.rgb.size() == static_cast<std::size_t>(map.width) * map.height * 3, "texels do not fit the size");
  for (const float value : map.rgb) fuzz::require(std::isfinite(value) && value >= 0.0f, "a texel not finite or < 0");
  return 0;
}
