// The exported Blender scripts rendered by a real Blender (headless Cycles on the CPU), compared ring by ring with
// skinlayer's own implementation of that Blender's Principled BSDF for the parameters the script carries; and,
// reported, with skinlayer's exact BRDF for the material it was fitted to (issues 44 and 54). The Blender is
// SKINLAYER_BLENDER_COMMAND (a command line, its words separated by '|': `blender`, or
// tests/app/export/blender_in_chroot.sh with a chroot of Debian's Blender 4.3 or 5.2); its version picks the export:
// `--format blender-3.4` and core/targets/principled_bsdf.h before 4.0, `--format blender` and
// core/targets/cycles_principled.h after.
//
// The exported script builds the material and its preview scene: a unit sphere under an orthographic camera on +z.
// tests/app/export/blender_lighting.py then lights it (a white furnace, or a delta sun of irradiance 1) and writes
// the linear pixels. Each pixel sees the sphere's normal n = (x, y, sqrt(1 - x^2 - y^2)) at its centre, from the
// view +z, so its radiance is known in closed form from the BSDF:
//   furnace   L = int f(omega_i, v) cos_i d omega_i, the light sent toward the view under a white sky;
//   sun       L = f(l, v) cos_i, with l toward the sun.
// Pixels are grouped in rings of equal angle (the view's for the furnace, the light's for the sun), 10 degrees wide,
// up to 80 degrees from the view; a ring's mean is compared with the mean of the predictions at its pixels. The
// Monte Carlo noise of a ring's mean is measured from its pixels: the spread of (render - prediction) over sqrt(n).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/material/presets.h"
#include "app/process/parallel_for.h"
#include "app/solution/document_albedo.h"
#include "app/solution/pair_evaluation.h"
#include "app/solution/solved_document.h"
#include "core/conventions.h"
#include "core/targets/cycles_principled.h"
#include "core/targets/principled_bsdf.h"
#include "tests/app/principled_report.h"
#include "tests/app/process_runner.h"
#include "tests/app/scratch_folder.h"

namespace skinlayer::test {
namespace {

constexpr int kSize = 96;            // pixels per side: ~5,700 on the sphere up to 80 degrees
constexpr int kSamples = 64;         // Cycles samples per pixel
constexpr double kOrthoScale = 2.2;  // the preview scene's camera, app/export/blender_script.cpp
const Vec3 kTowardSun = Vec3(-0.5, 0.4, 0.77).normalized();
// How much further a furnace render's ring may be from the exact material than the fit's own albedo is there (per
// channel): the render's noise and what the node and skinlayer's model of it may differ by. The fit reports its
// albedo error at 0, 20, ..., 80 degrees only, and a ring between them can be off by more (clear-coat-red's red at
// 70-80 degrees: 3.2% against 2.3% at 80), so the ring's own error is the measure, from the same pixels.
constexpr double kFurnaceAllowance = 0.005;

struct Pixel {
  Vec3 normal;
  Rgb rendered;
};

// The Blender under test: its command line, and its major version (from `--version`).
std::vector<std::string> blender_command() {
  std::vector<std::string> command;
  std::stringstream list(SKINLAYER_BLENDER_COMMAND);
  for (std::string word; std::getline(list, word, '|');) command.push_back(word);
  return command;
}

// Blender's version as major * 100 + minor (403 for 4.3.2), from `--version`.
int blender_version() {
  static const int version = [] {
    std::vector<std::string> argv = blender_command();
    argv.push_back("--version");
    const ProcessResult result = run_process(argv);
    const std::size_t at = result.out.find("Blender ");
    const std::size_t dot = at == std::string::npos ? at : result.out.find('.', at);
    if (result.exit_code != 0 || dot == std::string::npos) {
      throw std::runtime_error("cannot tell the version of " + std::string(SKINLAYER_BLENDER_COMMAND) + ": " +
                               result.out + result.err);
    }
    return 100 * std::stoi(result.out.substr(at + 8)) + std::stoi(result.out.substr(dot + 1));
  }();
  return version;
}
int blender_major_version() { return blender_version() / 100; }

// The export whose node this Blender has.
std::string blender_format() { return blender_major_version() >= 4 ? "blender" : "blender-3.4"; }

// skinlayer's model of the node the script built in this Blender (its coat before 4.4 too), from the script's fit
// report: f cos(theta_i) for light omega_i seen from omega_o, and the light sent toward a view at theta under a white
// sky.
struct NodeModel {
  std::function<Rgb(const Vec3&, const Vec3&)> brdf_cosine;
  std::function<Rgb(double theta)> albedo;
  bool clearcoat = false;  // Blender 3.4's clearcoat, which Cycles 3.4 samples with the wrong density
};

NodeModel node_model(const nlohmann::json& report) {
  if (report.at("target") == "principled-3.4") {
    const PrincipledParameters p = principled_parameters(report);
    return {[p](const Vec3& i, const Vec3& o) { return principled_brdf_cosine_weighted(p, i, o); },
            [p](double theta) { return principled_albedo(p, Vec3(std::sin(theta), 0.0, std::cos(theta)), 32); },
            p.clearcoat > 0.0};
  }
  CyclesPrincipledParameters parameters = cycles_principled_parameters(report);
  parameters.release = blender_version() < 404 ? CyclesRelease::kBlender4_0To4_3 : CyclesRelease::kBlender4_4On;
  const CyclesPrincipled node(parameters);
  return {[node](const Vec3& i, const Vec3& o) { return node.brdf_cosine_weighted(i, o); },
          [node](double theta) { return node.albedo(std::cos(theta)); }, false};
}

// The script's fit report (tests/app/principled_report.h reads its Principled parameters).
nlohmann::json fit_report(const std::string& script) {
  const std::string start = "SKINLAYER_FIT = json.loads(r\"\"\"";
  const std::size_t begin = script.find(start);
  if (begin == std::string::npos) throw std::runtime_error("the script has no SKINLAYER_FIT");
  const std::size_t end = script.find("\"\"\")", begin + start.size());
  return nlohmann::json::parse(script.substr(begin + start.size(), end - begin - start.size()));
}

// The pixels on the sphere whose footprint lies inside it, up to 80 degrees from the view.
std::vector<Pixel> sphere_pixels(const std::string& path) {
  std::ifstream in(path);
  int width = 0, height = 0;
  in >> width >> height;
  if (width != kSize || height != kSize) throw std::runtime_error("unexpected image size in " + path);
  std::vector<Pixel> pixels;
  const double step = kOrthoScale / kSize, half_diagonal = step / std::sqrt(2.0);
  for (int row = 0; row < height; ++row) {  // from the bottom, as Blender stores them
    for (int column = 0; column < width; ++column) {
      Rgb value;
      in >> value(0) >> value(1) >> value(2);
      const double x = -0.5 * kOrthoScale + (column + 0.5) * step, y = -0.5 * kOrthoScale + (row + 0.5) * step;
      const double r = std::hypot(x, y);
      if (r + half_diagonal >= 1.0 || std::sqrt(1.0 - r * r) < std::cos(degrees_to_radians(80.0))) continue;
      pixels.push_back({Vec3(x, y, std::sqrt(1.0 - r * r)), value});
    }
  }
  if (!in) throw std::runtime_error("short image " + path);
  return pixels;
}

// A world direction in the frame of the normal n (any tangent: the BSDFs are isotropic).
Vec3 local(const Vec3& n, const Vec3& w) {
  const Vec3 t = (std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
  const Vec3 b = n.cross(t);
  return {t.dot(w), b.dot(w), n.dot(w)};
}

struct Ring {
  int pixels = 0;
  Rgb rendered = Rgb::Zero(), principled = Rgb::Zero(), exact = Rgb::Zero(), noise = Rgb::Zero();
};

// Ring means over 10-degree rings of the angle `angle_of` gives (radians), and each ring's measured noise.
template <typename AngleOf>
std::vector<Ring> rings(const std::vector<Pixel>& pixels, const std::vector<Rgb>& principled,
                        const std::vector<Rgb>& exact, AngleOf angle_of) {
  std::vector<Ring> out(8);
  std::vector<Rgb> squares(8, Rgb::Zero());
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    const int index = static_cast<int>(radians_to_degrees(angle_of(pixels[k])) / 10.0);
    if (index < 0 || index >= 8) continue;
    Ring& ring = out[static_cast<std::size_t>(index)];
    ++ring.pixels;
    ring.rendered += pixels[k].rendered;
    ring.principled += principled[k];
    ring.exact += exact[k];
    squares[static_cast<std::size_t>(index)] += (pixels[k].rendered - principled[k]).square();
  }
  for (std::size_t r = 0; r < out.size(); ++r) {
    Ring& ring = out[r];
    if (ring.pixels < 2) continue;
    const double n = ring.pixels;
    ring.rendered /= n;
    ring.principled /= n;
    ring.exact /= n;
    const Rgb bias = ring.rendered - ring.principled;
    ring.noise = ((squares[r] / n - bias.square()).max(0.0) * n / (n - 1.0)).sqrt() / std::sqrt(n);
  }
  return out;
}

class BlenderRender : public ScratchFolderTest {
 public:
  // Exports the preset's fitted script with its preview scene, relights and renders it; returns the script's text
  // and the pixels.
  std::pair<std::string, std::vector<Pixel>> render(const std::string& preset, const std::string& mode) {
    const std::string script = path(preset + ".py"), image = path(mode + ".txt");
    const ProcessResult exported =
        run_skinlayer({"export", "--format", blender_format(), "--scene", "--preset", preset, "-o", script});
    if (exported.exit_code != 0) throw std::runtime_error("export failed: " + exported.err);
    std::vector<std::string> argv = blender_command();
    argv.insert(argv.end(),
                {"-b", "--factory-startup", "--python-exit-code", "1", "--python", script, "--python",
                 SKINLAYER_BLENDER_LIGHTING, "--", mode, std::to_string(kSize), std::to_string(kSamples), image});
    if (mode == "sun") {
      for (int c = 0; c < 3; ++c) argv.push_back(std::to_string(kTowardSun(c)));
    }
    const ProcessResult rendered = run_process(argv);
    if (rendered.exit_code != 0 || rendered.out.find("Error") != std::string::npos) {
      throw std::runtime_error("blender failed (" + std::to_string(rendered.exit_code) + "): " + rendered.out +
                               rendered.err);
    }
    std::ifstream in(script);
    std::stringstream text;
    text << in.rdbuf();
    return {text.str(), sphere_pixels(image)};
  }
};

// Checks each ring against skinlayer's model of the node, prints it with the exact material's ring, and returns, per
// channel, the worst relative difference between the render and the exact material over the rings, and the worst
// excess of it over the fit's own difference there (skinlayer's node against the exact material).
struct ExactDifference {
  Rgb worst = Rgb::Zero(), excess = Rgb::Constant(-1.0);
};
ExactDifference compare(const std::vector<Ring>& ring_list, const char* what) {
  ExactDifference exact;
  double worst = 0.0, noisiest = 0.0;
  std::printf("  %s: ring  pixels  Blender (r g b)  skinlayer's node  exact  noise\n", what);
  for (std::size_t r = 0; r < ring_list.size(); ++r) {
    const Ring& ring = ring_list[r];
    if (ring.pixels < 20) continue;
    for (int c = 0; c < 3; ++c) {
      if (ring.principled(c) < 1e-4) continue;  // a channel that reflects nothing here
      const double relative = ring.rendered(c) / ring.principled(c) - 1.0;
      const double noise = ring.noise(c) / ring.principled(c);
      EXPECT_LT(noise, 0.007) << what << " ring " << r << " channel " << c << ": too noisy to judge 2%";
      EXPECT_LT(std::abs(relative), 0.02)
          << what << " ring " << 10 * r << "-" << 10 * r + 10 << " degrees, channel " << c << ": Blender "
          << ring.rendered(c) << ", skinlayer's node " << ring.principled(c) << " (noise " << ring.noise(c) << ")";
      const double off = std::abs(ring.rendered(c) / ring.exact(c) - 1.0);
      exact.worst(c) = std::max(exact.worst(c), off);
      exact.excess(c) = std::max(exact.excess(c), off - std::abs(ring.principled(c) / ring.exact(c) - 1.0));
      worst = std::max(worst, std::abs(relative));
      noisiest = std::max(noisiest, noise);
    }
    std::printf("  %2zu-%2zu deg %5d  %.4f %.4f %.4f  %.4f %.4f %.4f  %.4f %.4f %.4f  %.1e\n", 10 * r, 10 * r + 10,
                ring.pixels, ring.rendered(0), ring.rendered(1), ring.rendered(2), ring.principled(0),
                ring.principled(1), ring.principled(2), ring.exact(0), ring.exact(1), ring.exact(2),
                ring.noise.maxCoeff());
  }
  std::printf("  %s: worst ring %.2f%% from skinlayer's node, noise of a ring's mean up to %.2f%%\n", what,
              100.0 * worst, 100.0 * noisiest);
  return exact;
}

// Under a white furnace every pixel is the light the BSDF sends toward its view: skinlayer's model of the node
// within 2% in every ring. Against the exact material, the render shows the fit's albedo error, and may be no further
// from it than the fit itself in the same ring, plus kFurnaceAllowance. Not for Blender 3.4's clearcoat: Cycles 3.4
// samples its half vectors from GGX but weighs them as GTR1's, so under any sky it renders another BSDF than it
// evaluates (jade's fit: 5.4% bright in red at the centre); under the sun, where only the evaluation counts, it is
// exact.
void check_furnace(BlenderRender& test, const std::string& preset) {
  const auto [script, pixels] = test.render(preset, "furnace");
  const nlohmann::json fit = fit_report(script);
  const NodeModel node = node_model(fit);
  if (node.clearcoat) GTEST_SKIP() << preset << "'s fit has a clearcoat, which Cycles 3.4 samples wrongly";
  // Both albedos on half-degree steps, interpolated to each pixel's view angle.
  std::vector<double> angles;
  for (int k = 0; k <= 170; ++k) angles.push_back(degrees_to_radians(0.5 * k));
  std::vector<Rgb> principled_table;
  for (const double angle : angles) {
    principled_table.push_back(node.albedo(angle));
  }
  const std::vector<Rgb> exact_table = document_reflectance_rgb(preset_material(preset), angles, parallel_for_threads);
  const auto at = [&](const std::vector<Rgb>& table, double angle) {
    const double position = std::min(radians_to_degrees(angle) / 0.5, 169.999);
    const auto k = static_cast<std::size_t>(position);
    const double t = position - static_cast<double>(k);
    return Rgb((1.0 - t) * table[k] + t * table[k + 1]);
  };
  std::vector<Rgb> principled, exact_values;
  for (const Pixel& pixel : pixels) {
    const double angle = std::acos(pixel.normal.z());
    principled.push_back(at(principled_table, angle));
    exact_values.push_back(at(exact_table, angle));
  }
  const ExactDifference exact =
      compare(rings(pixels, principled, exact_values, [](const Pixel& pixel) { return std::acos(pixel.normal.z()); }),
              (preset + ", furnace").c_str());
  const std::vector<double> reported = fit.at("errors").at("albedo_worst").get<std::vector<double>>();
  std::printf(
      "  %s furnace: the render against the exact material, worst ring %.1f / %.1f / %.1f%%; the fit "
      "reported %.1f / %.1f / %.1f%% at 0, 20, ..., 80 degrees; beyond the fit's own error in a ring by up to "
      "%.2f / %.2f / %.2f%%\n",
      preset.c_str(), 100.0 * exact.worst(0), 100.0 * exact.worst(1), 100.0 * exact.worst(2), 100.0 * reported[0],
      100.0 * reported[1], 100.0 * reported[2], 100.0 * exact.excess(0), 100.0 * exact.excess(1),
      100.0 * exact.excess(2));
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(exact.excess(c), kFurnaceAllowance)
        << "channel " << c << ": the render is further from the exact material than the fit is";
  }
}

// Under the sun every pixel is f(l, v) cos_i: skinlayer's model of the node within 2% in every ring about the light.
void check_sun(BlenderRender& test, const std::string& preset) {
  const auto [script, pixels] = test.render(preset, "sun");
  const NodeModel node = node_model(fit_report(script));
  std::vector<Rgb> principled;
  std::vector<std::size_t> lit;  // the pixels the sun reaches, whose exact BRDF is asked for
  std::vector<Vec3> lights, views;
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    const Vec3 light = local(pixels[k].normal, kTowardSun), view = local(pixels[k].normal, Vec3::UnitZ());
    principled.push_back(node.brdf_cosine(light, view));
    if (light.z() <= 0.0) continue;
    lit.push_back(k);
    lights.push_back(light);
    views.push_back(view);
  }
  // The exact material's f cos(theta_i) at the lit pixels (0 where the sun is below the horizon).
  const std::vector<Rgb> brdf =
      brdf_rgb(solve_document(preset_material(preset), SubsurfaceModel::Stam, parallel_for_threads), lights, views,
               parallel_for_threads);
  std::vector<Rgb> exact(pixels.size(), Rgb::Zero());
  for (std::size_t j = 0; j < lit.size(); ++j) exact[lit[j]] = brdf[j] * lights[j].z();
  const ExactDifference difference =
      compare(rings(pixels, principled, exact,
                    [](const Pixel& pixel) { return std::acos(std::clamp(pixel.normal.dot(kTowardSun), -1.0, 1.0)); }),
              (preset + ", sun").c_str());
  std::printf("  %s sun: the render against the exact material, worst ring %.1f%%\n", preset.c_str(),
              100.0 * difference.worst.maxCoeff());
}

// The preview scene as exported renders to a file with Blender's own command line, as docs/examples/blender says
// (shrunk to 10% and 4 samples for the test).
TEST_F(BlenderRender, ThePreviewSceneRendersFromTheCommandLine) {
  const std::string script = path("wax.py");
  ASSERT_EQ(
      run_skinlayer({"export", "--format", blender_format(), "--scene", "--preset", "wax", "-o", script}).exit_code, 0);
  std::vector<std::string> argv = blender_command();
  argv.insert(argv.end(), {"-b", "--factory-startup", "--python-exit-code", "1", "--python", script, "--python-expr",
                           "import bpy; scene = bpy.context.scene; scene.render.resolution_percentage = 10; "
                           "scene.cycles.samples = 4",
                           "-o", path("preview_####"), "-F", "PNG", "-f", "1"});
  const ProcessResult rendered = run_process(argv);
  EXPECT_EQ(rendered.exit_code, 0) << rendered.err;
  EXPECT_EQ(rendered.out.find("Error"), std::string::npos) << rendered.out;
  EXPECT_TRUE(std::filesystem::exists(path("preview_0001.png"))) << rendered.out;
}

// The script made for the other node stops Blender at once, with one line naming the export to make, and renders
// nothing, even without --python-exit-code.
TEST_F(BlenderRender, TheOtherNodesScriptStopsWithOneLine) {
  const std::string other = blender_format() == "blender" ? "blender-3.4" : "blender";
  const std::string script = path("other.py");
  ASSERT_EQ(run_skinlayer({"export", "--format", other, "--scene", "--preset", "wax", "-o", script}).exit_code, 0);
  std::vector<std::string> argv = blender_command();
  argv.insert(argv.end(),
              {"-b", "--factory-startup", "--python", script, "-o", path("other_####"), "-F", "PNG", "-f", "1"});
  const ProcessResult rendered = run_process(argv);
  EXPECT_EQ(rendered.exit_code, 1) << rendered.out << rendered.err;
  EXPECT_NE(rendered.err.find("skinlayer export --format " + blender_format() + "`"), std::string::npos)
      << rendered.err;
  EXPECT_FALSE(std::filesystem::exists(path("other_0001.png")));
}

// Every preset, under a white furnace and under the sun.
class EveryPreset : public BlenderRender, public ::testing::WithParamInterface<std::string> {};
TEST_P(EveryPreset, UnderAWhiteFurnaceIsSkinlayersNode) { check_furnace(*this, GetParam()); }
TEST_P(EveryPreset, UnderTheSunIsSkinlayersNode) { check_sun(*this, GetParam()); }
INSTANTIATE_TEST_SUITE_P(BlenderRender, EveryPreset, ::testing::ValuesIn(preset_names()),
                         [](const ::testing::TestParamInfo<std::string>& preset) {
                           std::string name = preset.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace skinlayer::test
