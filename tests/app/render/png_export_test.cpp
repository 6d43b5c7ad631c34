// skinlayer render writes a PNG that decodes at the requested size and is not blank; a path that cannot be written
// is a clear one-line error.
#include <gtest/gtest.h>
#include <stb_image.h>  // libstb.so holds the implementation

#include <array>
#include <filesystem>
#include <sstream>
#include <string>

#include "tests/app/process_runner.h"

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
  const ProcessResult result =
      run_render("render --size 300x200 --albedo 0.9,0.6,0.5 --light-theta 30 -o " + out.string());
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

// The sums of the red, green and blue of each third's central 30 x 30 square of a 300 x 100 compare view (the
// spheres Lambert | Hanrahan-Krueger | layer model, left to right).
std::array<std::array<double, 3>, 3> compare_view_sums(const std::filesystem::path& png) {
  std::array<std::array<double, 3>, 3> sums{};
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(png.c_str(), &width, &height, &channels, 4);
  EXPECT_NE(pixels, nullptr) << png;
  if (pixels == nullptr) return sums;
  EXPECT_EQ(width, 300);
  for (int k = 0; k < 3; ++k) {
    for (int y = 35; y < 65; ++y) {
      for (int x = 100 * k + 25; x < 100 * k + 55; ++x) {
        for (int c = 0; c < 3; ++c) sums[k][c] += pixels[4 * (y * width + x) + c];
      }
    }
  }
  stbi_image_free(pixels);
  return sums;
}

// The side-by-side comparison (Lambert | Hanrahan-Krueger | layer model): three spheres, and Hanrahan-Krueger's
// single scattering returns visibly less light than the layer it leaves multiple scattering out of.
TEST(PngExport, CompareViewDrawsThreeModels) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "skinlayer_compare_test.png";
  const ProcessResult result = run_render("render --view compare --size 300x100 --T 0.05 -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto sums = compare_view_sums(out);
  EXPECT_GT(sums[0][1], 0.0);
  EXPECT_LT(sums[1][1], 0.8 * sums[2][1]) << "HK " << sums[1][1] << " layer " << sums[2][1];
}

// A skin compares too: the comparison models take the RGB layer that stands for it (app/solution/skin_comparison.h),
// so the Lambert sphere sends back the skin's colour, red above blue as the skin's own sphere.
TEST(PngExport, CompareViewTakesASkin) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "skinlayer_compare_skin_test.png";
  const ProcessResult result = run_render("render --view compare --size 300x100 --preset skin-fair -o " + out.string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto sums = compare_view_sums(out);
  for (const int k : {0, 2}) EXPECT_GT(sums[k][0], 1.2 * sums[k][2]) << "sphere " << k << " is skin-coloured";
  EXPECT_LT(sums[1][1], 0.8 * sums[2][1]) << "HK's single scattering is darker than the layer";
}

TEST(PngExport, UnwritablePathIsAClearError) {
  const ProcessResult result = run_render("render --size 64x64 -o /nonexistent-folder/x.png");
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.err.find("/nonexistent-folder/x.png"), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
}

// --sphere-radius spreads the subsurface light of a side-lit, weakly absorbing half-space with lengths (mu_t 2/mm, so
// its light spreads over millimetres) over a 5 mm sphere: the night side beyond the terminator, black without it,
// is lit, and redder than it is blue (the red channel absorbs least).
TEST(PngExport, ASphereRadiusSpreadsTheLightPastTheTerminator) {
  const std::filesystem::path plain = std::filesystem::temp_directory_path() / "skinlayer_render_plain.png";
  const std::filesystem::path spread = std::filesystem::temp_directory_path() / "skinlayer_render_spread.png";
  const std::string material =
      "render --view sphere --size 96x96 --light-theta 80 --sigma 0.4 --T 0 --g 0.8 "
      "--mu-t 2 --albedo 0.995,0.98,0.9 -o ";
  ASSERT_EQ(run_render(material + plain.string()).exit_code, 0);
  const ProcessResult result = run_render(material + spread.string() + " --sphere-radius 5");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  // Mean RGB over a 10 x 20 block right of the centre: the light comes from the left, 80 degrees from the view, so
  // these normals face 100 degrees and more away from it.
  const auto night_side = [](const std::filesystem::path& png) {
    std::array<double, 3> mean{};
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(png.c_str(), &width, &height, &channels, 4);
    EXPECT_NE(pixels, nullptr) << png;
    if (pixels == nullptr) return mean;
    for (int y = 38; y < 58; ++y) {
      for (int x = 62; x < 72; ++x) {
        for (int c = 0; c < 3; ++c) mean[c] += pixels[4 * (y * width + x) + c] / 200.0;
      }
    }
    stbi_image_free(pixels);
    return mean;
  };
  const std::array<double, 3> dark = night_side(plain), lit = night_side(spread);
  EXPECT_LT(dark[0], 1.0);
  EXPECT_GT(lit[0], 20.0);
  EXPECT_GT(lit[0], lit[2]);
}

TEST(PngExport, BadRenderFlagsNameTheFlag) {
  EXPECT_NE(run_render("render --size 10x10 -o /tmp/x.png").err.find("size"), std::string::npos);
  EXPECT_NE(run_render("render --view cube -o /tmp/x.png").err.find("view"), std::string::npos);
  EXPECT_NE(run_render("render --albedo 0.5,2,0.5 -o /tmp/x.png").err.find("albedo"), std::string::npos);
  EXPECT_NE(run_render("render").err.find("-o"), std::string::npos);
  EXPECT_NE(run_render("render --sphere-radius 0 -o /tmp/x.png").err.find("sphere-radius"), std::string::npos);
  // A sphere in mm needs the material's lengths, and a material with a profile.
  EXPECT_NE(run_render("render --T 0 --albedo 0.9 --sphere-radius 10 -o /tmp/x.png").err.find("mu-t"),
            std::string::npos);
  EXPECT_NE(run_render("render --mu-t 5 --sphere-radius 10 -o /tmp/x.png").err.find("profile"), std::string::npos);
}

// A picture name render cannot write, and an environment that is neither built in nor a file: exit 2 and one line
// that says what to give, before anything is solved or written.
TEST(PngExport, AnUnwritablePictureNameOrAnUnknownEnvironmentSaysWhatToGive) {
  const std::filesystem::path jpeg = std::filesystem::temp_directory_path() / "skinlayer_render_test.jpg";
  std::filesystem::remove(jpeg);
  const ProcessResult as_jpeg = run_render("render --size 32x32 -o " + jpeg.string());
  EXPECT_EQ(as_jpeg.exit_code, 2);
  EXPECT_NE(as_jpeg.err.find(".png"), std::string::npos) << as_jpeg.err;
  EXPECT_NE(as_jpeg.err.find(".hdr"), std::string::npos) << as_jpeg.err;
  EXPECT_FALSE(std::filesystem::exists(jpeg));
  const ProcessResult typo = run_render("render --size 32x32 --env studoi -o /tmp/x.png");
  EXPECT_EQ(typo.exit_code, 2);
  for (const char* word : {"studoi", "furnace", "studio", "sky", "FILE.hdr"}) {
    EXPECT_NE(typo.err.find(word), std::string::npos) << word << ": " << typo.err;
  }
  const ProcessResult folder =
      run_render("render --size 32x32 --env " + std::filesystem::temp_directory_path().string() + " -o /tmp/x.png");
  EXPECT_EQ(folder.exit_code, 2);
  EXPECT_NE(folder.err.find("is a folder"), std::string::npos) << folder.err;
}

}  // namespace
}  // namespace skinlayer::test
