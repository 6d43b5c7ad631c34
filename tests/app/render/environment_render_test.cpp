// `skinlayer render --env` against independent facts, from its linear .hdr output (OSMesa):
//   * the furnace: under uniform radiance 1 a pixel whose normal makes angle theta with the view shows the
//     directional reflectance R(theta) that `skinlayer albedo` prints (reciprocity: int f cos = R), within 1%;
//   * a .hdr file that holds a constant radiance gives the furnace's picture;
//   * a tiny bright patch gives the directional light's picture (the validated path) within the noise.
// The tests write their own .hdr files (stb_image_write); nothing is downloaded.
#include <gtest/gtest.h>
#include <stb_image.h>  // libstb.so holds the implementations
#include <stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/gl/osmesa_context.h"
#include "app/render/environment_map.h"
#include "app/render/render_target.h"
#include "app/render/renderer.h"
#include "app/render/table_textures.h"
#include "app/solution/material_solve.h"
#include "core/solver.h"
#include "tests/app/process_runner.h"

namespace skinlayer {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;
constexpr int kSize = 48;
constexpr double kMargin = 1.08;  // Renderer::kSphereMargin: the view shows 1.08 sphere radii each side

struct Picture {
  int width = 0, height = 0;
  std::vector<float> rgb;
  double at(int x, int y, int c) const { return rgb[(static_cast<std::size_t>(y) * width + x) * 3 + c]; }
};

Picture read_hdr(const fs::path& path) {
  Picture picture;
  int channels = 0;
  const std::unique_ptr<float, void (*)(void*)> data(
      stbi_loadf(path.c_str(), &picture.width, &picture.height, &channels, 3), stbi_image_free);
  EXPECT_TRUE(data) << path;
  if (data) picture.rgb.assign(data.get(), data.get() + std::size_t{3} * picture.width * picture.height);
  return picture;
}

fs::path temporary(const std::string& stem, const std::string& extension) {
  return fs::temp_directory_path() / ("skinlayer_env_" + stem + "_" + std::to_string(::getpid()) + extension);
}

// The pixel centre's point on the view in sphere radii (x right, y up), and its normal's angle to the view.
std::pair<double, double> pixel_point(int x, int y) {
  const double px = ((x + 0.5) / kSize * 2.0 - 1.0) * kMargin, py = (1.0 - (y + 0.5) / kSize * 2.0) * kMargin;
  return {px, py};
}

Picture render(const std::vector<std::string>& flags, const fs::path& out) {
  std::vector<std::string> command = {
      "render", "--view", "sphere", "--size", std::to_string(kSize) + "x" + std::to_string(kSize), "-o", out.string()};
  command.insert(command.end(), flags.begin(), flags.end());
  const test::ProcessResult result = test::run_skinlayer(command);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  Picture picture = read_hdr(out);
  fs::remove(out);
  return picture;
}

// An equirectangular .hdr written here: radiance(direction) at each texel centre, with the convention of
// app/render/environment_map.h restated: theta = pi v from +y, phi = 2 pi u, d = (sin theta sin phi, cos theta,
// sin theta cos phi).
template <class Radiance>
void write_environment(const fs::path& path, int width, const Radiance& radiance) {
  const int height = width / 2;
  std::vector<float> rgb(static_cast<std::size_t>(width) * height * 3);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double theta = kPi * (j + 0.5) / height, phi = 2.0 * kPi * (i + 0.5) / width;
      const double value = radiance(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi),
                                    (2.0 * kPi / width) * (kPi / height) * std::sin(theta));
      for (int c = 0; c < 3; ++c) rgb[(static_cast<std::size_t>(j) * width + i) * 3 + c] = static_cast<float>(value);
    }
  }
  ASSERT_TRUE(stbi_write_hdr(path.c_str(), width, height, 3, rgb.data()));
}

// The mean of each ring of pixels (1.5 degrees wide about `ring`) of a picture's sphere, channel 0.
double ring_mean(const Picture& picture, double ring) {
  double sum = 0.0;
  int count = 0;
  for (int y = 0; y < picture.height; ++y) {
    for (int x = 0; x < picture.width; ++x) {
      const auto [px, py] = pixel_point(x, y);
      const double r = std::hypot(px, py);
      if (r >= 1.0 || std::abs(std::asin(r) * 180.0 / kPi - ring) > 1.5) continue;
      sum += picture.at(x, y, 0);
      ++count;
    }
  }
  return count ? sum / count : -1.0;
}

TEST(EnvironmentRender, AConstantHdrFileGivesTheFurnacesPicture) {
  const fs::path constant = temporary("constant", ".hdr");
  write_environment(constant, 100, [](double, double, double, double) { return 1.0; });
  const Picture from_file = render({"--env", constant.string(), "--samples", "512"}, temporary("a", ".hdr"));
  const Picture furnace = render({"--env", "furnace", "--samples", "512"}, temporary("b", ".hdr"));
  fs::remove(constant);
  ASSERT_EQ(from_file.width, kSize);
  ASSERT_EQ(furnace.width, kSize);
  for (double ring : {10.0, 35.0, 60.0, 75.0}) {
    EXPECT_NEAR(ring_mean(from_file, ring), ring_mean(furnace, ring), 0.01 * ring_mean(furnace, ring)) << ring;
  }
  // The background shows the environment: 1 everywhere off the sphere.
  EXPECT_NEAR(from_file.at(0, 0, 0), 1.0, 0.01);
}

// In linear radiance the backdrop is light or nothing: a hidden environment, and a picture without one, leave zero
// radiance behind the sphere (so that it composites and a furnace check finds the sphere); shown, it is the
// environment's radiance. The PNG keeps its flat display colour.
TEST(EnvironmentRender, AHiddenBackdropIsZeroRadianceInLinearOutput) {
  const Picture hidden = render({"--env", "furnace", "--samples", "8", "--background", "hide"}, temporary("h", ".hdr"));
  const Picture directional = render({}, temporary("n", ".hdr"));
  const Picture shown = render({"--env", "furnace", "--samples", "8", "--background", "show"}, temporary("s", ".hdr"));
  ASSERT_EQ(hidden.width, kSize);
  ASSERT_EQ(directional.width, kSize);
  ASSERT_EQ(shown.width, kSize);
  const int far = kSize - 1;
  for (const auto& [x, y] : {std::pair{0, 0}, std::pair{far, 0}, std::pair{0, far}, std::pair{far, far}}) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(hidden.at(x, y, c), 0.0) << x << "," << y << " channel " << c;
      EXPECT_EQ(directional.at(x, y, c), 0.0) << x << "," << y << " channel " << c;
      EXPECT_NEAR(shown.at(x, y, c), 1.0, 0.01) << x << "," << y << " channel " << c;
    }
  }
  // The sphere itself is lit in all three.
  EXPECT_GT(hidden.at(kSize / 2, kSize / 2, 0), 0.1);
  EXPECT_GT(directional.at(kSize / 2, kSize / 2, 0), 0.1);
  // The PNG's backdrop is the flat colour, not black.
  const fs::path png = temporary("h", ".png");
  const test::ProcessResult drawn =
      test::run_skinlayer({"render", "--view", "sphere", "--size", "48x48", "--env", "furnace", "--samples", "8",
                           "--background", "hide", "-o", png.string()});
  ASSERT_EQ(drawn.exit_code, 0) << drawn.err;
  int width = 0, height = 0, channels = 0;
  const std::unique_ptr<unsigned char, void (*)(void*)> pixels(stbi_load(png.c_str(), &width, &height, &channels, 3),
                                                               stbi_image_free);
  fs::remove(png);
  ASSERT_TRUE(pixels);
  EXPECT_GT(pixels.get()[0], 0);
  EXPECT_GT(pixels.get()[2], pixels.get()[0]);  // the backdrop's slight blue
}

// A patch 2 degrees in radius whose radiance times its solid angle is the directional light's irradiance (pi)
// lights the sphere as that light does, at every lit pixel well inside the terminator.
TEST(EnvironmentRender, ATinyBrightPatchGivesTheDirectionalLightsPicture) {
  const double theta = 40.0 * kPi / 180.0, phi = kPi;  // the render command's light: from the left
  const double l[3] = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
  const double cos_radius = std::cos(2.0 * kPi / 180.0);
  double solid_angle = 0.0;
  const auto inside = [&](double x, double y, double z) { return x * l[0] + y * l[1] + z * l[2] > cos_radius; };
  const fs::path patch = temporary("patch", ".hdr");
  write_environment(patch, 512, [&](double x, double y, double z, double texel) {
    if (inside(x, y, z)) solid_angle += texel;
    return 0.0;
  });
  write_environment(patch, 512,
                    [&](double x, double y, double z, double) { return inside(x, y, z) ? kPi / solid_angle : 0.0; });
  const std::vector<std::string> material = {"--sigma", "0.4", "--albedo", "0.9"};
  std::vector<std::string> lit = {"--env", patch.string(), "--samples", "256", "--background", "hide"};
  lit.insert(lit.end(), material.begin(), material.end());
  std::vector<std::string> directional = {"--light-theta", "40", "--light-phi", "180"};
  directional.insert(directional.end(), material.begin(), material.end());
  const Picture by_patch = render(lit, temporary("p", ".hdr"));
  const Picture by_light = render(directional, temporary("d", ".hdr"));
  fs::remove(patch);
  ASSERT_EQ(by_patch.width, kSize);
  ASSERT_EQ(by_light.width, kSize);
  int checked = 0;
  double worst = 0.0;
  for (int y = 2; y < kSize; y += 3) {
    for (int x = 2; x < kSize; x += 3) {
      const auto [px, py] = pixel_point(x, y);
      const double r2 = px * px + py * py;
      if (r2 > 0.9) continue;
      const double n[3] = {px, py, std::sqrt(1.0 - r2)};
      if (n[0] * l[0] + n[1] * l[1] + n[2] * l[2] < 0.2) continue;  // near the terminator the patch is partly below
      const double want = by_light.at(x, y, 0), got = by_patch.at(x, y, 0);
      EXPECT_NEAR(got, want, 0.03 * want) << "pixel " << x << "," << y;
      worst = std::max(worst, std::abs(got - want) / want);
      ++checked;
    }
  }
  EXPECT_GT(checked, 40);
  std::printf("patch against directional light: %d pixels, worst %.2f%%\n", checked, 100.0 * worst);
}

TEST(EnvironmentRender, BadEnvironmentsAndFlagsAreOneLineErrors) {
  const fs::path out = temporary("bad", ".png");
  const auto fails = [&](std::vector<std::string> flags, int code, const std::string& text) {
    std::vector<std::string> command = {"render"};
    if (std::ranges::find(flags, "-o") == flags.end()) command.insert(command.end(), {"-o", out.string()});
    command.insert(command.end(), flags.begin(), flags.end());
    const test::ProcessResult result = test::run_skinlayer(command);
    EXPECT_EQ(result.exit_code, code) << result.err;
    EXPECT_NE(result.err.find(text), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  };
  // No such file is a mistake on the command line (exit 2), named with the built-ins; a file that is no image, 1.
  fails({"--env", "/nonexistent/sky.hdr"}, 2, "/nonexistent/sky.hdr");
  const fs::path text_file = temporary("text", ".hdr");
  { std::ofstream(text_file) << "not an image\n"; }
  fails({"--env", text_file.string()}, 1, text_file.string());
  fs::remove(text_file);
  const fs::path square = temporary("square", ".hdr");
  const std::vector<float> pixels(16 * 16 * 3, 1.0f);
  ASSERT_TRUE(stbi_write_hdr(square.c_str(), 16, 16, 3, pixels.data()));
  fails({"--env", square.string()}, 1, "equirectangular");
  fs::remove(square);
  fails({"--env", "studio", "--samples", "0"}, 2, "samples");
  fails({"--env-ev", "2"}, 2, "--env");
  fails({"--env", "sky", "--background", "fog"}, 2, "show, blur, hide");
  fails({"--tonemap", "filmic"}, 2, "exponential, aces, none");
  fails({"--light", "off"}, 2, "--env");
  fails({"--env", "sky", "--view", "both", "-o", temporary("x", ".hdr").string()}, 2, "--view sphere");
  EXPECT_FALSE(fs::exists(out));
}

// llvmpipe stops a shader's loops after 65535 iterations in all (renderer.cpp, samples_per_draw): one call of many
// samples must add exactly what many small passes add (the same sequence points, summed in another order).
TEST(EnvironmentRender, OneCallOfManySamplesAddsWhatManySmallPassesAdd) {
  const int size = 16;
  gl::OsmesaContext context(size, size);
  Renderer renderer;
  renderer.upload_environment(*builtin_environment("studio"));
  ColorMaterial sharp;  // more modes than the default: more loop iterations per sample
  sharp.layer.sigma = 0.15;
  sharp.layer.g = 0.9;
  const ColorTables tables = solve_color(sharp, 0.0);
  renderer.upload(make_table_textures(tables));
  const SurfaceParams surface{sharp.layer.eta, sharp.layer.sigma};
  constexpr int kSamples = 1024;
  EnvironmentAccumulation once(size, size), passes(size, size);
  renderer.accumulate_environment(once, {}, surface, kSamples);
  for (int pass = 0; pass < kSamples / 16; ++pass) renderer.accumulate_environment(passes, {}, surface, 16);
  ASSERT_EQ(once.samples(), kSamples);
  ASSERT_EQ(passes.samples(), kSamples);
  const std::vector<float> a = once.target().read_rgba32f(), b = passes.target().read_rgba32f();
  double worst = 0.0;  // relative, over every channel of every estimated texel (RGB sums and the sample count)
  int estimated = 0;
  for (std::size_t i = 0; i < a.size(); i += 4) {
    ASSERT_EQ(a[i + 3] > 0.0f, b[i + 3] > 0.0f) << "texel " << i / 4;  // texels far outside the limb are skipped
    if (b[i + 3] == 0.0f) continue;
    ++estimated;
    for (std::size_t c = 0; c < 4; ++c) {
      ASSERT_GT(b[i + c], 0.0f) << "texel " << i / 4;
      worst = std::max(worst, std::abs(static_cast<double>(a[i + c]) / b[i + c] - 1.0));
    }
  }
  EXPECT_GT(estimated, size * size / 2);
  EXPECT_LT(worst, 1e-4) << "modes " << tables.channels[0].modes();
}

// In process, from the float target (no .hdr quantization): rings of pixels at one angle each (the furnace is
// symmetric about the view axis), their mean against the mean of R at each pixel's own angle.
TEST(EnvironmentRender, TheFurnaceShowsTheDirectionalReflectanceAtEveryAngle) {
  const int size = 96;
  gl::OsmesaContext context(size, size);
  Renderer renderer;
  renderer.upload_environment(*builtin_environment("furnace"));
  RenderTarget target(size, size, PixelFormat::Rgba32F);
  ColorMaterial paper;  // the paper's default
  ColorMaterial bone;   // over a Lambertian base, RGB
  bone.layer.sigma = 0.3;
  bone.layer.g = 0.3;
  bone.layer.bottom = parse_bottom("lambert:0.6");
  bone.albedo_rgb = {0.9, 0.7, 0.5};
  ColorMaterial clear;  // a thin, rough, denser layer over a matched bottom
  clear.layer.sigma = 0.6;
  clear.layer.eta = 1.5;
  clear.layer.tau = optical_depth_from_transparency(0.5);
  clear.albedo_rgb = {0.95, 0.95, 0.95};
  clear.layer.bottom = parse_bottom("matched");
  for (const ColorMaterial& material : {paper, bone, clear}) {
    const ColorTables tables = solve_color(material, 0.0);
    renderer.upload(make_table_textures(tables));
    EnvironmentAccumulation accumulation(size, size);
    const SurfaceParams surface{material.layer.eta, material.layer.sigma};
    for (int pass = 0; pass < 128; ++pass) renderer.accumulate_environment(accumulation, {}, surface, 8);
    SphereView view;
    view.irradiance = 0.0;
    view.linear_output = true;
    view.environment = EnvironmentView{0.0, 1.0, EnvironmentBackground::Hide};
    target.bind();
    renderer.draw_sphere(view, {material.layer.eta, material.layer.sigma}, {0, 0, size, size}, 0, &accumulation);
    RenderTarget::unbind();
    const std::vector<float> pixels = target.read_rgba32f();
    for (double ring : {10.0, 30.0, 50.0, 65.0, 75.0}) {
      std::vector<double> theta;
      std::vector<std::array<double, 3>> shown;
      const std::array<double, 2> extent = view_extent({0, 0, size, size}, Renderer::kSphereMargin);
      for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
          const double px = ((x + 0.5) / size * 2.0 - 1.0) * extent[0];
          const double py = (1.0 - (y + 0.5) / size * 2.0) * extent[1];
          const double r = std::hypot(px, py);
          if (r >= 1.0 || std::abs(std::asin(r) * 180.0 / kPi - ring) > 1.5) continue;
          theta.push_back(std::asin(r));
          const float* pixel = &pixels[(static_cast<std::size_t>(y) * size + x) * 4];
          shown.push_back({pixel[0], pixel[1], pixel[2]});
        }
      }
      ASSERT_GE(theta.size(), 8u) << ring;
      std::vector<Material> channels(3, material.layer);
      for (int c = 0; c < 3; ++c) channels[c].albedo = material.albedo_rgb[c];
      const auto albedos = directional_albedo(std::span<const Material>(channels), theta);
      for (int c = 0; c < 3; ++c) {
        double mean_shown = 0.0, mean_expected = 0.0;
        for (std::size_t k = 0; k < theta.size(); ++k) {
          mean_shown += shown[k][c] / static_cast<double>(theta.size());
          mean_expected += albedos[c][k].reflectance() / static_cast<double>(theta.size());
        }
        EXPECT_NEAR(mean_shown, mean_expected, 0.01 * mean_expected)
            << "ring " << ring << " degrees, channel " << c << ", " << theta.size() << " pixels, sigma "
            << material.layer.sigma;
        std::printf("furnace sigma %.1f ring %2.0f channel %d: %.5f against R %.5f (%+.2f%%, %zu pixels)\n",
                    material.layer.sigma, ring, c, mean_shown, mean_expected,
                    100.0 * (mean_shown / mean_expected - 1.0), theta.size());
      }
    }
  }
}

}  // namespace
}  // namespace skinlayer
