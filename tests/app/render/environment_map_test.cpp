// The .hdr environment reader (app/render/environment_map.h, radiance_hdr_scan.h), GL-free: files written by
// stb_image_write read back; damaged, truncated, empty and oversized ones are refused with one line, at once
// (stb_image alone hangs on a run of length 0 and reads zeros past the end).
#include "app/render/environment_map.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>  // libstb.so holds the implementation

#include <cmath>
#include <glm/matrix.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace skinlayer {
namespace {

// A width x height .hdr in memory (run-length coded from 8 pixels wide, as stb_image_write does).
std::string hdr_file(int width, int height, std::vector<float>* written = nullptr) {
  std::vector<float> rgb(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t n = 0; n < rgb.size(); ++n) rgb[n] = 0.25f + static_cast<float>(n % 7) * 0.5f;
  std::string bytes;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
  };
  EXPECT_TRUE(stbi_write_hdr_to_func(append, &bytes, width, height, 3, rgb.data()));
  if (written) *written = rgb;
  return bytes;
}

std::string refusal(const std::string& bytes) {
  try {
    decode_hdr_environment(bytes, "env.hdr");
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("env.hdr"), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "read " << bytes.size() << " bytes";
  return "";
}

TEST(EnvironmentMap, FlatAndRunLengthCodedFilesReadBackWithinRgbeRounding) {
  for (const auto& [width, height] : {std::pair{4, 2}, std::pair{32, 16}}) {
    std::vector<float> written;
    const EnvironmentMap map = decode_hdr_environment(hdr_file(width, height, &written), "env.hdr");
    ASSERT_EQ(map.width, width);
    ASSERT_EQ(map.height, height);
    ASSERT_EQ(map.rgb.size(), written.size());
    for (std::size_t n = 0; n < written.size(); ++n) EXPECT_NEAR(map.rgb[n], written[n], written[n] / 128) << n;
  }
}

TEST(EnvironmentMap, EveryTruncationIsRefusedAsTruncated) {
  const std::string full = hdr_file(32, 16);
  const std::size_t pixels = full.find("+X 32\n") + 6;
  for (std::size_t length = pixels; length < full.size(); length += 7) {
    EXPECT_NE(refusal(full.substr(0, length)).find("truncated"), std::string::npos) << length;
  }
}

TEST(EnvironmentMap, ARunOfLengthZeroIsRefusedInsteadOfHanging) {
  std::string file = hdr_file(32, 16);
  const std::size_t first_run = file.find("+X 32\n") + 6 + 4;  // after the first scanline's marker
  file[first_run] = 0;
  EXPECT_NE(refusal(file).find("bad run-length data in scanline 0"), std::string::npos);
}

TEST(EnvironmentMap, EmptyAndOversizedHeadersAreRefusedBeforeAnyPixelIsRead) {
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";
  EXPECT_NE(refusal(header + "-Y 0 +X 0\n").find("no pixels"), std::string::npos);
  EXPECT_NE(refusal(header + "-Y 8192 +X 16384\n").find("larger than 8192x4096"), std::string::npos);
  EXPECT_NE(refusal(header + "-Y 10 +X 12\n" + std::string(40, '\x01')).find("not equirectangular"), std::string::npos);
  EXPECT_NE(refusal("P6\n2 1\n255\nabcdef").find("not a Radiance .hdr image"), std::string::npos);
}

// A map's directions and coordinates are inverses, and turning the environment by alpha about +y shifts what a
// direction sees by -alpha / (2 pi) in u (environment_map.h's conventions; shaders/environment.glsl applies the same
// matrix), leaving v alone. The matrix is a rotation: its transpose is its inverse, and +y stays put.
TEST(EnvironmentMap, TurningTheEnvironmentShiftsTheLongitude) {
  constexpr double kTwoPi = 6.283185307179586;
  for (const double alpha : {0.0, 0.4, -1.3, 3.0}) {
    const glm::dmat3 from_world = environment_from_world(alpha);
    const glm::dmat3 product = glm::transpose(from_world) * from_world;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(product[c][r], r == c ? 1.0 : 0.0, 1e-15);
    }
    const glm::dvec3 up = from_world * glm::dvec3(0.0, 1.0, 0.0);
    EXPECT_NEAR(up.y, 1.0, 1e-15);
    for (const double u : {0.1, 0.35, 0.5, 0.9}) {
      for (const double v : {0.2, 0.5, 0.8}) {
        const glm::dvec2 back = environment_coordinates(environment_direction(u, v));
        EXPECT_NEAR(back.x, u, 1e-12);
        EXPECT_NEAR(back.y, v, 1e-12);
        const glm::dvec2 seen = environment_coordinates(from_world * environment_direction(u, v));
        double expected_u = std::fmod(u - alpha / kTwoPi, 1.0);
        if (expected_u < 0.0) expected_u += 1.0;
        EXPECT_NEAR(seen.x, expected_u, 1e-12) << "alpha " << alpha << " u " << u;
        EXPECT_NEAR(seen.y, v, 1e-12);
      }
    }
  }
}

}  // namespace
}  // namespace skinlayer
