// skinlayer render writes a PNG that decodes at the requested size and is not blank; a path that cannot be written
// is a clear one-line error.
#include <gtest/gtest.h>
#include <stb_image.h>  // libstb.so holds the implementation

#include "tests/app/process_runner.h"

#include <filesystem>
#include <sstream>
#include <string>

namespace skinlayer::test {
namespace {

// skinlayer render with space-separated arguments.
ProcessResult run_render(const std::string& arguments) {
  std::vector<std::string> argv;
  std::istringstream words(arguments);
  for (std::string word; words >> word;) argv.push_back(word);
  return run_skinlayer(argv);
}

TEST(PngExport, RenderWritesADecodablePictureOfTheRequestedSize) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "skinlayer_render_test.png";
  std::filesystem::remove(out);
  const ProcessResult result = run_render("render --size 300x200 --albedo 0.9,0.6,0.5 --light-theta 30 -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(out.c_str(), &width, &height, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(width, 300);
  EXPECT_EQ(height, 200);
  double sum = 0.0, sum2 = 0.0;
  const int count = width * height;
  for (int k = 0; k < count; ++k) {
    const double luma = pixels[4 * k] + pixels[4 * k + 1] + pixels[4 * k + 2];
    sum += luma;
    sum2 += luma * luma;
  }
  stbi_image_free(pixels);
  const double variance = sum2 / count - (sum / count) * (sum / count);
  EXPECT_GT(variance, 100.0);  // not blank
}

// The side-by-side comparison (Lambert | Hanrahan-Krueger | layer model): three spheres, and Hanrahan-Krueger's
// single scattering returns visibly less light than the layer it leaves multiple scattering out of.
TEST(PngExport, CompareViewDrawsThreeModels) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "skinlayer_compare_test.png";
  const ProcessResult result = run_render("render --view compare --size 300x100 --T 0.05 -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(out.c_str(), &width, &height, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  EXPECT_EQ(width, 300);
  std::array<double, 3> brightness{};  // mean green of each third's central square
  for (int k = 0; k < 3; ++k) {
    for (int y = 35; y < 65; ++y) {
      for (int x = 100 * k + 25; x < 100 * k + 55; ++x) brightness[k] += pixels[4 * (y * width + x) + 1];
    }
  }
  stbi_image_free(pixels);
  EXPECT_GT(brightness[0], 0.0);
  EXPECT_LT(brightness[1], 0.8 * brightness[2]) << "HK " << brightness[1] << " layer " << brightness[2];
}

// A skin compares too: the comparison models take the RGB layer that stands for it (app/solution/skin_comparison.h),
// so the Lambert sphere sends back the skin's colour, red above blue as the skin's own sphere.
TEST(PngExport, CompareViewTakesASkin) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "skinlayer_compare_skin_test.png";
  const ProcessResult result = run_render("render --view compare --size 300x100 --preset skin-fair -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(out.c_str(), &width, &height, &channels, 4);
  ASSERT_NE(pixels, nullptr);
  std::array<std::array<double, 3>, 3> mean{};  // each third's central square, per channel
  for (int k = 0; k < 3; ++k) {
    for (int y = 35; y < 65; ++y) {
      for (int x = 100 * k + 25; x < 100 * k + 55; ++x) {
        for (int c = 0; c < 3; ++c) mean[k][c] += pixels[4 * (y * width + x) + c];
      }
    }
  }
  stbi_image_free(pixels);
  for (const int k : {0, 2}) EXPECT_GT(mean[k][0], 1.2 * mean[k][2]) << "sphere " << k << " is skin-coloured";
  EXPECT_LT(mean[1][1], 0.8 * mean[2][1]) << "HK's single scattering is darker than the layer";
}

TEST(PngExport, UnwritablePathIsAClearError) {
  const ProcessResult result = run_render("render --size 64x64 -o /nonexistent-folder/x.png");
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.err.find("/nonexistent-folder/x.png"), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

TEST(PngExport, BadRenderFlagsNameTheFlag) {
  EXPECT_NE(run_render("render --size 10x10 -o /tmp/x.png").err.find("size"), std::string::npos);
  EXPECT_NE(run_render("render --view cube -o /tmp/x.png").err.find("view"), std::string::npos);
  EXPECT_NE(run_render("render --albedo 0.5,2,0.5 -o /tmp/x.png").err.find("albedo"), std::string::npos);
  EXPECT_NE(run_render("render").err.find("-o"), std::string::npos);
}

}  // namespace
}  // namespace skinlayer::test
