// The .hdr environment reader (app/render/environment_map.h, radiance_hdr_scan.h), GL-free: files written by
// stb_image_write read back; damaged, truncated, empty and oversized ones are refused with one line, at once
// (stb_image alone hangs on a run of length 0 and reads zeros past the end).
#include "app/render/environment_map.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>  // libstb.so holds the implementation

#include <cmath>
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

}  // namespace
}  // namespace skinlayer
