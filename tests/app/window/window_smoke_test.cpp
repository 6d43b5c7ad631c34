// The GLFW window path, end to end: `skinlayer --capture FILE` under Xvfb (start, render, screenshot through the
// app's own export, exit), and the one-line error without a display.
#include <gtest/gtest.h>
#include <stb_image.h>  // libstb.so holds the implementation: no STB_IMAGE_IMPLEMENTATION here
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

std::filesystem::path temporary_png(const std::string& stem) {
  return std::filesystem::temp_directory_path() / (stem + "-" + std::to_string(::getpid()) + ".png");
}

bool one_line(const std::string& text) { return !text.empty() && text.find('\n') == text.size() - 1; }

TEST(WindowSmoke, CaptureUnderXvfbWritesTheWholeWindow) {
  const std::optional<std::string> xvfb_run = find_in_path("xvfb-run");
  if (!xvfb_run)
    GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth); the window smoke test needs it";
  const std::filesystem::path png = temporary_png("skinlayer-window-capture");
  std::filesystem::remove(png);

  const ProcessResult result = run_process({*xvfb_run, "-a", "-s", "-screen 0 1280x720x24", SKINLAYER_EXECUTABLE,
                                            "--capture", png.string(), "--sigma", "0.3"});
  ASSERT_EQ(result.exit_code, 0) << "stdout: " << result.out << "\nstderr: " << result.err;

  // "wrote FILE (WxH)": the framebuffer size the window reported.
  const std::regex wrote("wrote (.+) \\((\\d+)x(\\d+)\\)\n");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(result.out, match, wrote)) << result.out;
  EXPECT_EQ(match[1].str(), png.string());
  const int framebuffer_width = std::stoi(match[2].str());
  const int framebuffer_height = std::stoi(match[3].str());
  EXPECT_GT(framebuffer_width, 0);
  EXPECT_LE(framebuffer_width, 1280);  // the Xvfb screen
  EXPECT_LE(framebuffer_height, 720);

  int width = 0, height = 0, channels = 0;
  const std::unique_ptr<unsigned char, void (*)(void*)> pixels(stbi_load(png.c_str(), &width, &height, &channels, 4),
                                                               stbi_image_free);
  ASSERT_NE(pixels, nullptr) << "the capture does not decode as PNG: " << png;
  EXPECT_EQ(width, framebuffer_width);
  EXPECT_EQ(height, framebuffer_height);

  // Not blank: the luminance varies, and the picture has the sphere's shading and the UI's many colors.
  double sum = 0.0, sum_squares = 0.0;
  const std::size_t count = static_cast<std::size_t>(width) * height;
  for (std::size_t k = 0; k < count; ++k) {
    const unsigned char* p = pixels.get() + 4 * k;
    const double luminance = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    sum += luminance;
    sum_squares += luminance * luminance;
  }
  const double mean = sum / static_cast<double>(count);
  const double variance = sum_squares / static_cast<double>(count) - mean * mean;
  std::printf("[ capture ] %dx%d, luminance mean %.1f, variance %.1f\n", width, height, mean, variance);
  EXPECT_GT(variance, 0.0);
  std::filesystem::remove(png);
}

// The previewer takes render's material flags (RGB --albedo included), --material and --preset; its capture carries
// the material it shows, which --material reads back.
TEST(WindowSmoke, CaptureTakesMaterialFilesPresetsAndRgbAlbedoAndRemembersThem) {
  const std::optional<std::string> xvfb_run = find_in_path("xvfb-run");
  if (!xvfb_run) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const std::filesystem::path json = temporary_png("skinlayer-window-material").replace_extension(".json");
  ASSERT_EQ(
      run_process({SKINLAYER_EXECUTABLE, "material", "--sigma", "0.3", "--T", "0.05", "-o", json.string()}).exit_code,
      0);
  struct Case {
    std::vector<std::string> flags;
    std::vector<std::string> remembered;  // in `skinlayer material --material capture.png`
  };
  const std::vector<Case> cases = {
      {{"--material", json.string(), "--albedo", "0.95,0.7,0.55"}, {"\"sigma\": 0.3", "0.05", "0.7", "0.55"}},
      {{"--preset", "jade"}, {"\"sigma\": 0.08", "1.62"}},
  };
  for (const Case& c : cases) {
    const std::filesystem::path png = temporary_png("skinlayer-window-remembers");
    std::vector<std::string> argv = {*xvfb_run,   "-a",        "-s", "-screen 0 1280x720x24", SKINLAYER_EXECUTABLE,
                                     "--capture", png.string()};
    argv.insert(argv.end(), c.flags.begin(), c.flags.end());
    const ProcessResult captured = run_process(argv);
    ASSERT_EQ(captured.exit_code, 0) << captured.err;
    const ProcessResult material = run_process({SKINLAYER_EXECUTABLE, "material", "--material", png.string()});
    ASSERT_EQ(material.exit_code, 0) << material.err;
    for (const std::string& part : c.remembered) EXPECT_NE(material.out.find(part), std::string::npos) << material.out;
    std::filesystem::remove(png);
  }
  std::filesystem::remove(json);
}

// The window's own test hook (--test-actions) drives undo, redo, drop and save as the keys and the mouse would;
// the capture's material and the printed titles show the outcome.
struct Scripted {
  ProcessResult run;
  std::string material;  // `skinlayer material --material capture.png`
};

Scripted run_scripted(const std::string& actions, const std::filesystem::path& config) {
  const std::optional<std::string> xvfb_run = find_in_path("xvfb-run");
  const std::filesystem::path png = temporary_png("skinlayer-window-scripted");
  std::filesystem::remove(png);
  Scripted result;
  result.run = run_process({"env", "XDG_CONFIG_HOME=" + config.string(), *xvfb_run, "-a", "-s", "-screen 0 1280x720x24",
                            SKINLAYER_EXECUTABLE, "--capture", png.string(), "--test-actions", actions});
  if (result.run.exit_code == 0) {
    result.material = run_process({SKINLAYER_EXECUTABLE, "material", "--material", png.string()}).out;
  }
  std::filesystem::remove(png);
  return result;
}

TEST(WindowSmoke, UndoRedoDropAndSaveThroughTheWindowsTestHook) {
  if (!find_in_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const std::filesystem::path dir = temporary_png("skinlayer-window-files").replace_extension("");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "thin.json").string();
  ASSERT_EQ(run_process({SKINLAYER_EXECUTABLE, "material", "--sigma", "0.2", "--T", "0.05", "-o", file}).exit_code, 0);

  // Two edits, two undos, one redo: the first edit stands.
  Scripted undo = run_scripted("set sigma 0.3;set g 0.5;undo;undo;redo", dir / "config");
  ASSERT_EQ(undo.run.exit_code, 0) << undo.run.err;
  EXPECT_NE(undo.material.find("\"sigma\": 0.3"), std::string::npos) << undo.material;
  EXPECT_NE(undo.material.find("\"g\": 0.8"), std::string::npos) << undo.material;

  // A drop over unsaved changes asks first; discarding them loads the dropped file, and the title names it.
  Scripted drop = run_scripted("set g 0.3;drop " + file + ";title;discard;title", dir / "config");
  ASSERT_EQ(drop.run.exit_code, 0) << drop.run.err;
  EXPECT_NE(drop.run.out.find("title: skinlayer - untitled *\n"), std::string::npos) << drop.run.out;
  EXPECT_NE(drop.run.out.find("title: skinlayer - thin.json\n"), std::string::npos) << drop.run.out;
  EXPECT_NE(drop.material.find("\"sigma\": 0.2"), std::string::npos) << drop.material;
  EXPECT_NE(drop.material.find("\"T\": 0.05"), std::string::npos) << drop.material;
  EXPECT_NE(drop.material.find("\"g\": 0.8"), std::string::npos) << drop.material;

  // A preset from the presets menu replaces the material; the title names it.
  Scripted preset = run_scripted("preset wax;title", dir / "config");
  ASSERT_EQ(preset.run.exit_code, 0) << preset.run.err;
  EXPECT_NE(preset.run.out.find("title: skinlayer - preset wax\n"), std::string::npos) << preset.run.out;
  EXPECT_NE(preset.material.find("\"name\": \"wax\""), std::string::npos) << preset.material;

  // Save as: the file holds the edit, the title loses its mark, and the recent list remembers it.
  const std::string saved = (dir / "saved.json").string();
  Scripted save = run_scripted("set albedo 0.6;title;save " + saved + ";title", dir / "config");
  ASSERT_EQ(save.run.exit_code, 0) << save.run.err;
  EXPECT_NE(save.run.out.find("title: skinlayer - saved.json\n"), std::string::npos) << save.run.out;
  const ProcessResult reread = run_process({SKINLAYER_EXECUTABLE, "material", "--material", saved});
  EXPECT_NE(reread.out.find("\"albedo\": 0.6"), std::string::npos) << reread.out;
  std::ifstream recent(dir / "config" / "skinlayer" / "recent.json");
  const std::string recent_text((std::istreambuf_iterator<char>(recent)), std::istreambuf_iterator<char>());
  EXPECT_NE(recent_text.find(saved), std::string::npos) << recent_text;
  std::filesystem::remove_all(dir);
}

// The layers panel (issue 12) through the same hook: add a layer, reorder, undo; the captured picture remembers the
// stack that was on screen.
TEST(WindowSmoke, TheLayersPanelAddsReordersAndUndoesLayers) {
  if (!find_in_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const std::filesystem::path dir = temporary_png("skinlayer-window-layers").replace_extension("");
  std::filesystem::create_directories(dir);
  // Add a layer (a copy of the default's, T 0.2), make the top one thinner, then move it down: T 0.2 over T 0.5.
  Scripted moved = run_scripted("layer add;set T 0.5;layer down 1", dir / "config");
  ASSERT_EQ(moved.run.exit_code, 0) << moved.run.err;
  const std::size_t first = moved.material.find("\"T\": 0.2");
  const std::size_t second = moved.material.find("\"T\": 0.5");
  EXPECT_NE(first, std::string::npos) << moved.material;
  EXPECT_NE(second, std::string::npos) << moved.material;
  EXPECT_LT(first, second) << "the moved layer is second: " << moved.material;
  // Undo takes the stack back to one layer, step by step.
  Scripted undone = run_scripted("layer add;set T 0.5;undo;undo", dir / "config");
  ASSERT_EQ(undone.run.exit_code, 0) << undone.run.err;
  EXPECT_EQ(undone.material.find("\"interface\""), std::string::npos);
  EXPECT_EQ(undone.material.find("\"T\": 0.2"), undone.material.rfind("\"T\": 0.2"))
      << "one layer: " << undone.material;
  // A preset stack shows and is remembered with its interface.
  Scripted coat = run_scripted("preset clear-coat-red", dir / "config");
  ASSERT_EQ(coat.run.exit_code, 0) << coat.run.err;
  EXPECT_NE(coat.material.find("\"interface\""), std::string::npos) << coat.material;
  std::filesystem::remove_all(dir);
}

// The Skin section (issue 25) through the same hook: a skin's slider, then "Match colour..." with a colour that a
// skin reaches (another skin's, from `albedo`), which sets melanin, blood and scattering as one undo step.
TEST(WindowSmoke, TheSkinSectionsSlidersAndMatchColourAreLiveAndUndoable) {
  if (!find_in_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const std::filesystem::path dir = temporary_png("skinlayer-window-skin").replace_extension("");
  std::filesystem::create_directories(dir);
  // The target: the normal-incidence colour of a darker skin, sRGB-encoded here (IEC 61966-2-1).
  const ProcessResult albedo = run_process({SKINLAYER_EXECUTABLE, "albedo", "--skin",
                                            "melanin=0.12,blood=0.02,scattering=1.5", "--theta-i", "0"});
  ASSERT_EQ(albedo.exit_code, 0) << albedo.err;
  const auto reflectance = [](const std::string& csv) {  // reflectance_r, _g, _b of the one row
    std::istringstream lines(csv);
    std::string header, row;
    std::getline(lines, header);
    std::getline(lines, row);
    std::vector<std::string> names, values;
    for (std::istringstream h(header); std::getline(h, names.emplace_back(), ',');) {}
    for (std::istringstream r(row); std::getline(r, values.emplace_back(), ',');) {}
    std::array<double, 3> rgb{};
    for (std::size_t i = 0; i < names.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        if (names[i] == std::string("reflectance_") + "rgb"[c]) rgb[c] = std::stod(values[i]);
      }
    }
    return rgb;
  };
  const std::array<double, 3> target = reflectance(albedo.out);
  std::string srgb;
  for (int c = 0; c < 3; ++c) {
    const double v = target[c] <= 0.0031308 ? 12.92 * target[c] : 1.055 * std::pow(target[c], 1.0 / 2.4) - 0.055;
    if (c > 0) srgb += ',';
    srgb += std::to_string(v);
  }
  const std::string slid = (dir / "slid.json").string(), matched = (dir / "matched.json").string();
  Scripted skin = run_scripted(
      "skin on;set melanin 0.2;save " + slid + ";match " + srgb + ";save " + matched + ";undo", dir / "config");
  ASSERT_EQ(skin.run.exit_code, 0) << skin.run.err;
  EXPECT_NE(skin.run.out.find("match: matched"), std::string::npos) << skin.run.out;
  const ProcessResult slid_file = run_process({SKINLAYER_EXECUTABLE, "material", "--material", slid});
  EXPECT_NE(slid_file.out.find("\"melanin\": 0.2"), std::string::npos) << slid_file.out;
  // The matched material gives the target within 0.5% per channel.
  const ProcessResult matched_albedo =
      run_process({SKINLAYER_EXECUTABLE, "albedo", "--material", matched, "--theta-i", "0"});
  ASSERT_EQ(matched_albedo.exit_code, 0) << matched_albedo.err;
  const std::array<double, 3> reached = reflectance(matched_albedo.out);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(reached[c], target[c], 5e-3 * target[c]) << "channel " << c;
  // One undo takes the whole match back: the capture shows the slid skin.
  EXPECT_NE(skin.material.find("\"melanin\": 0.2"), std::string::npos) << skin.material;
  EXPECT_NE(skin.material.find("\"blood\": 0.005"), std::string::npos) << skin.material;
  std::filesystem::remove_all(dir);
}

// Export MERL (issue 13) through the same hook: the shown material's table, written off the window's thread, whole,
// before the capture.
TEST(WindowSmoke, ExportMerlWritesTheShownMaterialsTable) {
  if (!find_in_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const std::filesystem::path dir = temporary_png("skinlayer-window-export").replace_extension("");
  std::filesystem::create_directories(dir);
  const std::filesystem::path merl = dir / "shown.png";  // the button writes the screenshot path with .binary
  Scripted exported = run_scripted("set albedo 0.5;export-merl " + merl.string(), dir / "config");
  ASSERT_EQ(exported.run.exit_code, 0) << exported.run.err;
  const std::filesystem::path written = dir / "shown.binary";
  EXPECT_NE(exported.run.out.find("saved " + written.string() + " (MERL, 34992012 bytes)"), std::string::npos)
      << exported.run.out;
  ASSERT_TRUE(std::filesystem::exists(written));
  EXPECT_EQ(std::filesystem::file_size(written), 34992012u);
  std::filesystem::remove_all(dir);
}

// Export BSDF the same way: the shown material's Fourier BSDF, whose metadata is that material (read back by
// `--material FILE.bsdf`; the file's structure and values are tested in tests/app/export).
TEST(WindowSmoke, ExportBsdfWritesTheShownMaterial) {
  if (!find_in_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const std::filesystem::path dir = temporary_png("skinlayer-window-bsdf").replace_extension("");
  std::filesystem::create_directories(dir);
  Scripted exported = run_scripted("set g 0.55;export-bsdf " + (dir / "shown.png").string(), dir / "config");
  ASSERT_EQ(exported.run.exit_code, 0) << exported.run.err;
  const std::filesystem::path written = dir / "shown.bsdf";
  ASSERT_TRUE(std::filesystem::exists(written));
  EXPECT_NE(exported.run.out.find("saved " + written.string() + " (SCATFUN, " +
                                  std::to_string(std::filesystem::file_size(written)) + " bytes)"),
            std::string::npos)
      << exported.run.out;
  const ProcessResult shown = run_process({SKINLAYER_EXECUTABLE, "material", "--material", written.string()});
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_NE(shown.out.find("\"g\": 0.55"), std::string::npos) << shown.out;
  std::filesystem::remove_all(dir);
}

// Export for pbrt-v4 / Mitsuba 3 (issue 26) the same way: the shown material's RGL tensor file, spectral, whose
// description is that material (the file's structure and values are tested in tests/app/export).
TEST(WindowSmoke, ExportRglWritesTheShownMaterialForPbrtV4AndMitsuba3) {
  if (!find_in_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const std::filesystem::path dir = temporary_png("skinlayer-window-rgl").replace_extension("");
  std::filesystem::create_directories(dir);
  Scripted exported = run_scripted("set g 0.55;export-rgl " + (dir / "shown.png").string(), dir / "config");
  ASSERT_EQ(exported.run.exit_code, 0) << exported.run.err;
  const std::filesystem::path written = dir / "shown.rgl.bsdf";
  ASSERT_TRUE(std::filesystem::exists(written));
  EXPECT_NE(exported.run.out.find("saved " + written.string() + " (RGL tensor, " +
                                  std::to_string(std::filesystem::file_size(written)) + " bytes)"),
            std::string::npos)
      << exported.run.out;
  std::ifstream in(written, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes.compare(0, 12, std::string("tensor_file\0", 12)), 0);
  EXPECT_NE(bytes.find("\"g\": 0.55"), std::string::npos) << "the description holds the shown material";
  EXPECT_NE(bytes.find("wavelengths"), std::string::npos) << "the spectral form";
  std::filesystem::remove_all(dir);
}

// Under an environment (issue 14) the window waits for the estimate's --samples before the capture, and shows the
// environment behind the sphere: the furnace's radiance 1 through the default exponential tone map, sRGB(1 - e^-1),
// 208 of 255, in the view's top right corner (the flat background is 0.02, 38 of 255). With --light off and the
// furnace, the sphere's pixels are its directional reflectance, below 1: darker than that corner.
TEST(WindowSmoke, CaptureUnderAnEnvironmentShowsItBehindTheSphere) {
  const std::optional<std::string> xvfb_run = find_in_path("xvfb-run");
  if (!xvfb_run) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const std::filesystem::path png = temporary_png("skinlayer-window-furnace");
  const ProcessResult result =
      run_process({*xvfb_run, "-a", "-s", "-screen 0 1280x720x24", SKINLAYER_EXECUTABLE, "--capture", png.string(),
                   "--view", "sphere", "--env", "furnace", "--samples", "64", "--background", "show"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  int width = 0, height = 0, channels = 0;
  const std::unique_ptr<unsigned char, void (*)(void*)> pixels(stbi_load(png.c_str(), &width, &height, &channels, 4),
                                                               stbi_image_free);
  ASSERT_NE(pixels, nullptr);
  const unsigned char* corner = pixels.get() + 4 * (static_cast<std::size_t>(height / 20) * width + width - 5);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(corner[c], 208, 2) << "channel " << c;
  // The sphere's centre: the middle of the picture area right of the panel, roughly; its brightest pixel on the
  // middle row is below the furnace's radiance.
  const unsigned char* middle_row = pixels.get() + 4 * (static_cast<std::size_t>(height / 2) * width);
  int darker = 0;
  for (int x = width / 2; x < width - width / 8; ++x) darker += middle_row[4 * x] < 200 ? 1 : 0;
  EXPECT_GT(darker, width / 8) << "the sphere's reflectance (< 1) shows darker than the furnace behind it";
  std::filesystem::remove(png);
}

// The translucency (issue 43): a skin lit from the side, 85 degrees from the view, on a 10 mm sphere. Once its BRDF is
// on screen the window computes its profile, and the capture waits for it: the sphere's middle row then has more lit
// pixels past the terminator than with the translucency off, and they are red (the light that travels far under skin
// is the red). The capture's "view" actions set the light and the sphere's radius.
TEST(WindowSmoke, ASideLitSkinBleedsRedPastTheTerminator) {
  const std::optional<std::string> xvfb_run = find_in_path("xvfb-run");
  if (!xvfb_run) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  // Lit pixels (any channel above 8) and their red excess on the sphere view's middle row, right of the picture
  // area's centre, where the light does not fall.
  const auto night_side = [&](const std::string& translucency) {
    const std::filesystem::path png = temporary_png("skinlayer-window-translucency-" + translucency);
    const ProcessResult result =
        run_process({*xvfb_run, "-a", "-s", "-screen 0 1280x720x24", SKINLAYER_EXECUTABLE, "--capture", png.string(),
                     "--view", "sphere", "--skin", "melanin=0.03", "--test-actions",
                     "view light-theta 85;view radius 10;view translucency " + translucency});
    EXPECT_EQ(result.exit_code, 0) << result.err;
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<unsigned char, void (*)(void*)> pixels(stbi_load(png.c_str(), &width, &height, &channels, 4),
                                                                 stbi_image_free);
    std::filesystem::remove(png);
    std::pair<int, double> lit{0, 0.0};
    if (pixels == nullptr) return lit;
    const unsigned char* row = pixels.get() + 4 * (static_cast<std::size_t>(height / 2) * width);
    const int panel = width * 3 / 10, centre = panel + (width - panel) / 2;
    for (int x = centre + 4; x < width - 4; ++x) {
      const unsigned char* p = row + 4 * x;
      if (std::max({p[0], p[1], p[2]}) > 8) {
        ++lit.first;
        lit.second += static_cast<double>(p[0]) - p[2];
      }
    }
    return lit;
  };
  const auto off = night_side("off"), on = night_side("on");
  std::printf("[ translucency ] lit pixels right of the centre: off %d, on %d (red excess %.0f)\n", off.first, on.first,
              on.second);
  EXPECT_GT(on.first, off.first + 10);
  EXPECT_GT(on.second, 0.0);
}

// The A/B comparison (issue 14): "pin" keeps the shown material as B, and the edits that follow change A only; the
// sphere shows A left of the split line and B right of it, and the screenshot's metadata carries B as a material
// file. A is made darker (albedo 0.3) than B (the default, 1), and compared with a capture of A alone.
TEST(WindowSmoke, PinningShowsTheEditedAndThePinnedMaterialSideBySide) {
  const std::optional<std::string> xvfb_run = find_in_path("xvfb-run");
  if (!xvfb_run) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const auto capture = [&](const std::filesystem::path& png, std::vector<std::string> extra) {
    std::vector<std::string> command = {
        *xvfb_run,    "-a",     "-s",    "-screen 0 1280x720x24", SKINLAYER_EXECUTABLE, "--capture",
        png.string(), "--view", "sphere"};
    command.insert(command.end(), extra.begin(), extra.end());
    const ProcessResult run = run_process(command);
    EXPECT_EQ(run.exit_code, 0) << run.err;
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> pixels(stbi_load(png.c_str(), &width, &height, &channels, 4),
                                                           stbi_image_free);
    return std::tuple{std::move(pixels), width, height};
  };
  const std::filesystem::path pinned_png = temporary_png("skinlayer-window-ab");
  const std::filesystem::path alone_png = temporary_png("skinlayer-window-a");
  const auto [pinned, width, height] = capture(pinned_png, {"--test-actions", "pin;set albedo 0.3;split 0.3"});
  // Under an environment both sides get an estimate, and the capture waits for both.
  const std::filesystem::path lit_png = temporary_png("skinlayer-window-ab-env");
  const auto [lit, lit_width, lit_height] =
      capture(lit_png, {"--env", "furnace", "--samples", "32", "--test-actions", "pin;set albedo 0.3;split 0.3"});
  ASSERT_NE(lit, nullptr);
  std::filesystem::remove(lit_png);
  const auto [alone, width_alone, height_alone] = capture(alone_png, {"--albedo", "0.3"});
  ASSERT_NE(pinned, nullptr);
  ASSERT_NE(alone, nullptr);
  ASSERT_EQ(width, width_alone);
  ASSERT_EQ(height, height_alone);
  // The middle row, on the lit sphere: pixels equal to A alone (left of the line) and pixels brighter (B, right).
  const std::size_t row = static_cast<std::size_t>(height / 2) * width;
  int same = 0, brighter = 0;
  for (int x = width / 3; x < width; ++x) {
    const int with_pin = pinned.get()[4 * (row + x) + 1], without = alone.get()[4 * (row + x) + 1];
    if (without < 20) continue;  // the background, or the sphere's unlit side
    if (std::abs(with_pin - without) <= 1) ++same;
    if (with_pin > without + 5) ++brighter;
  }
  EXPECT_GT(same, 20) << "left of the line: A, as without the pin";
  EXPECT_GT(brighter, 20) << "right of the line: B (albedo 1) is brighter than A (albedo 0.3)";
  std::ifstream file(pinned_png, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_NE(bytes.find("\"pinned\""), std::string::npos) << "the screenshot's metadata carries B";
  std::filesystem::remove(pinned_png);
  std::filesystem::remove(alone_png);
}

// A fitted shader as B (issue 44): "pin-fit openpbr" fits the shown jade and pins the fit, whose tables hold the
// OpenPBR Surface's BRDF. Right of the split line the sphere is the fit: close to the material (a good fit is within
// a few percent over most of the sphere), not the same pixels (it is not the material), and the screenshot says which
// B it shows.
TEST(WindowSmoke, AFittedShaderAsBSitsBesideTheMaterial) {
  const std::optional<std::string> xvfb_run = find_in_path("xvfb-run");
  if (!xvfb_run) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const auto capture = [&](const std::filesystem::path& png, const std::string& actions) {
    const ProcessResult run =
        run_process({*xvfb_run, "-a", "-s", "-screen 0 1280x720x24", SKINLAYER_EXECUTABLE, "--capture", png.string(),
                     "--view", "sphere", "--preset", "jade", "--test-actions", actions});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    int width = 0, height = 0, channels = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> pixels(stbi_load(png.c_str(), &width, &height, &channels, 4),
                                                           stbi_image_free);
    return std::tuple{std::move(pixels), width, height, run.out};
  };
  const std::filesystem::path fit_png = temporary_png("skinlayer-window-fit-b"),
                              alone_png = temporary_png("skinlayer-window-jade");
  const auto [fit, width, height, out] = capture(fit_png, "pin-fit openpbr;split 0");
  const auto [alone, width_alone, height_alone, out_alone] = capture(alone_png, "split 0");
  ASSERT_NE(fit, nullptr);
  ASSERT_NE(alone, nullptr);
  ASSERT_EQ(width, width_alone);
  EXPECT_NE(out.find("pinned B (OpenPBR fit): OpenPBR fit: lobe RMS"), std::string::npos) << out;
  // Split at the left edge: the whole sphere is B. Its lit pixels on the middle row against the material's.
  const std::size_t row = static_cast<std::size_t>(height / 2) * width;
  int lit = 0, close = 0, different = 0;
  for (int x = width / 3; x < width; ++x) {
    const int with_fit = fit.get()[4 * (row + x) + 1], material = alone.get()[4 * (row + x) + 1];
    if (material < 30) continue;  // the background, or the sphere's unlit side
    ++lit;
    if (std::abs(with_fit - material) <= 0.1 * material) ++close;
    if (with_fit != material) ++different;
  }
  std::printf("[ fit as B ] lit %d, within 10%% %d, different %d\n", lit, close, different);
  EXPECT_GT(lit, 50);
  EXPECT_GT(close, lit * 7 / 10) << "the fit looks like the material";
  EXPECT_GT(different, lit / 10) << "and is not the material";
  std::ifstream file(fit_png, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_NE(bytes.find("B (OpenPBR fit)"), std::string::npos) << "the screenshot's metadata says which B";
  std::filesystem::remove(fit_png);
  std::filesystem::remove(alone_png);
}

// Export Blender and Export MaterialX write the shown material's fits, as `skinlayer export` does.
TEST(WindowSmoke, ExportBlenderAndMaterialXWriteTheShownMaterialsFits) {
  if (!find_in_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const std::filesystem::path dir = temporary_png("skinlayer-window-fits").replace_extension("");
  std::filesystem::create_directories(dir);
  Scripted exported = run_scripted(
      "set g 0.55;export-blender " + (dir / "shown.png").string() + ";rest;export-mtlx " + (dir / "shown.png").string(),
      dir / "config");
  ASSERT_EQ(exported.run.exit_code, 0) << exported.run.err;
  // The material rides along: indented JSON in the script, compact JSON in an XML attribute in the MaterialX file.
  for (const auto& [name, g] : {std::pair{"shown.py", "\"g\": 0.55"}, std::pair{"shown.mtlx", "&quot;g&quot;:0.55"}}) {
    const std::filesystem::path written = dir / name;
    ASSERT_TRUE(std::filesystem::exists(written)) << exported.run.out;
    std::ifstream in(written);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find(g), std::string::npos) << name << " carries the shown material";
  }
  EXPECT_NE(exported.run.out.find("(Blender script, "), std::string::npos) << exported.run.out;
  EXPECT_NE(exported.run.out.find("(MaterialX, "), std::string::npos) << exported.run.out;
  std::filesystem::remove_all(dir);
}

// Quitting with unsaved changes asks first: the window is still there (it prints its title) until the changes are
// discarded, and then it closes by itself.
TEST(WindowSmoke, QuittingWithUnsavedChangesAsksFirst) {
  const std::optional<std::string> xvfb_run = find_in_path("xvfb-run");
  if (!xvfb_run) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth)";
  const ProcessResult result = run_process({*xvfb_run, "-a", "-s", "-screen 0 1280x720x24", SKINLAYER_EXECUTABLE,
                                            "--test-actions", "set g 0.3;quit;title;discard"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("title: skinlayer - untitled *\n"), std::string::npos) << result.out;
  // With nothing unsaved, quit quits at once: the action after it never runs.
  const ProcessResult saved = run_process(
      {*xvfb_run, "-a", "-s", "-screen 0 1280x720x24", SKINLAYER_EXECUTABLE, "--test-actions", "quit;title"});
  EXPECT_EQ(saved.exit_code, 0) << saved.err;
  EXPECT_EQ(saved.out.find("title:"), std::string::npos) << saved.out;
}

TEST(WindowSmoke, FlagsWithoutACommandOpenThePreviewer) {
  // `skinlayer --sigma 0.3` is the previewer (here without a display: its one-line error), not an unknown command.
  const ProcessResult result =
      run_process({"env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", SKINLAYER_EXECUTABLE, "--sigma", "0.3"});
  EXPECT_NE(result.exit_code, 0);
  EXPECT_TRUE(one_line(result.err)) << result.err;
  EXPECT_NE(result.err.find("skinlayer render"), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find("unknown command"), std::string::npos) << result.err;
}

TEST(WindowSmoke, WithoutADisplayOneLinePointsToRender) {
  const ProcessResult result = run_process({"env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", SKINLAYER_EXECUTABLE});
  EXPECT_NE(result.exit_code, 0);
  EXPECT_EQ(result.out, "");
  EXPECT_TRUE(one_line(result.err)) << result.err;
  EXPECT_NE(result.err.find("skinlayer render"), std::string::npos) << result.err;
  EXPECT_TRUE(result.err.starts_with("skinlayer: error: ")) << result.err;
}

TEST(WindowSmoke, CaptureFlagsAreCheckedBeforeAWindowOpens) {
  const ProcessResult result = run_process(
      {"env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", SKINLAYER_EXECUTABLE, "--capture", "x.png", "--sigma", "7"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(one_line(result.err)) << result.err;
  EXPECT_NE(result.err.find("sigma"), std::string::npos) << result.err;
}

// --test-actions @FILE reads the list from a file (the soak's thousands of actions); a missing one is named.
TEST(WindowSmoke, AnActionFileThatCannotBeReadIsNamedBeforeAWindowOpens) {
  const ProcessResult result =
      run_process({"env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", SKINLAYER_EXECUTABLE, "--capture", "x.png",
                   "--test-actions", "@/nonexistent/actions.txt"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(one_line(result.err)) << result.err;
  EXPECT_NE(result.err.find("test-actions"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("/nonexistent/actions.txt"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace skinlayer::test
