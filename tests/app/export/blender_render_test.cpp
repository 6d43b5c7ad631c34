// `skinlayer export --format blender --scene` rendered by the real Blender 3.4 (headless Cycles on the CPU), compared
// ring by ring with skinlayer's own Principled BSDF (core/targets/principled_bsdf.h) for the parameters the script
// carries; and, reported, with skinlayer's exact BRDF for the material it was fitted to (issue 44).
//
// The exported script builds the material and its preview scene: a unit sphere under an orthographic camera on +z.
// tests/app/export/blender_lighting.py then lights it (a white furnace, or a delta sun of irradiance 1) and writes
// the linear pixels. Each pixel sees the sphere's normal n = (x, y, sqrt(1 - x^2 - y^2)) at its centre, from the
// view +z, so its radiance is known in closed form from the BSDF:
//   furnace   L = int f(omega_i, v) cos_i d omega_i, the directional albedo at the view's angle (reciprocity);
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

struct Pixel {
  Vec3 normal;
  Rgb rendered;
};

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
        run_skinlayer({"export", "--format", "blender", "--scene", "--preset", preset, "-o", script});
    if (exported.exit_code != 0) throw std::runtime_error("export failed: " + exported.err);
    std::vector<std::string> argv = {"blender",
                                     "-b",
                                     "--factory-startup",
                                     "--python-exit-code",
                                     "1",
                                     "--python",
                                     script,
                                     "--python",
                                     SKINLAYER_BLENDER_LIGHTING,
                                     "--",
                                     mode,
                                     std::to_string(kSize),
                                     std::to_string(kSamples),
                                     image};
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

// Checks each ring against skinlayer's Principled BSDF, prints it with the exact material's ring, and returns the
// worst relative difference between the render and the exact material over the rings.
double compare(const std::vector<Ring>& ring_list, const char* what) {
  double worst_exact = 0.0, worst = 0.0, noisiest = 0.0;
  std::printf("  %s: ring  pixels  Blender (r g b)  principled  exact  noise\n", what);
  for (std::size_t r = 0; r < ring_list.size(); ++r) {
    const Ring& ring = ring_list[r];
    if (ring.pixels < 20) continue;
    for (int c = 0; c < 3; ++c) {
      if (ring.principled(c) < 1e-4) continue;  // a channel that reflects nothing here
      const double relative = ring.rendered(c) / ring.principled(c) - 1.0;
      const double noise = ring.noise(c) / ring.principled(c);
      EXPECT_LT(noise, 0.007) << what << " ring " << r << " channel " << c << ": too noisy to judge 2%";
      EXPECT_LT(std::abs(relative), 0.02) << what << " ring " << 10 * r << "-" << 10 * r + 10 << " degrees, channel "
                                          << c << ": Blender " << ring.rendered(c) << ", skinlayer's Principled "
                                          << ring.principled(c) << " (noise " << ring.noise(c) << ")";
      worst_exact = std::max(worst_exact, std::abs(ring.rendered(c) / ring.exact(c) - 1.0));
      worst = std::max(worst, std::abs(relative));
      noisiest = std::max(noisiest, noise);
    }
    std::printf("  %2zu-%2zu deg %5d  %.4f %.4f %.4f  %.4f %.4f %.4f  %.4f %.4f %.4f  %.1e\n", 10 * r, 10 * r + 10,
                ring.pixels, ring.rendered(0), ring.rendered(1), ring.rendered(2), ring.principled(0),
                ring.principled(1), ring.principled(2), ring.exact(0), ring.exact(1), ring.exact(2),
                ring.noise.maxCoeff());
  }
  std::printf("  %s: worst ring %.2f%% from skinlayer's Principled, noise of a ring's mean up to %.2f%%\n", what,
              100.0 * worst, 100.0 * noisiest);
  return worst_exact;
}

// Under a white furnace every pixel is the BSDF's directional albedo at its view angle: skinlayer's Principled
// within 2% in every ring. Against the exact material, the render shows the fit's albedo error, which may not
// exceed what the fit reported at 0-80 degrees by more than the rings' spread of angles allows (a ring averages
// 10 degrees of a curve the fit sampled every 20).
void check_furnace(BlenderRender& test, const std::string& preset) {
  const auto [script, pixels] = test.render(preset, "furnace");
  const nlohmann::json fit = fit_report(script);
  const PrincipledParameters parameters = principled_parameters(fit);
  // Both albedos on half-degree steps, interpolated to each pixel's view angle.
  std::vector<double> angles;
  for (int k = 0; k <= 170; ++k) angles.push_back(degrees_to_radians(0.5 * k));
  std::vector<Rgb> principled_table;
  for (const double angle : angles) {
    principled_table.push_back(principled_albedo(parameters, Vec3(std::sin(angle), 0.0, std::cos(angle)), 32));
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
  const double worst_exact =
      compare(rings(pixels, principled, exact_values, [](const Pixel& pixel) { return std::acos(pixel.normal.z()); }),
              (preset + ", furnace").c_str());
  const double reported = fit.at("errors").at("albedo_worst").get<std::vector<double>>().front();
  std::printf("  %s furnace: the render against the exact material, worst ring %.1f%%; the fit reported %.1f%%\n",
              preset.c_str(), 100.0 * worst_exact, 100.0 * reported);
  EXPECT_LT(worst_exact, reported + 0.02) << "the render's albedo error is more than the fit reported";
}

// Under the sun every pixel is f(l, v) cos_i: skinlayer's Principled within 2% in every ring about the light.
void check_sun(BlenderRender& test, const std::string& preset) {
  const auto [script, pixels] = test.render(preset, "sun");
  const PrincipledParameters parameters = principled_parameters(fit_report(script));
  std::vector<Rgb> principled;
  std::vector<std::size_t> lit;  // the pixels the sun reaches, whose exact BRDF is asked for
  std::vector<Vec3> lights, views;
  for (std::size_t k = 0; k < pixels.size(); ++k) {
    const Vec3 light = local(pixels[k].normal, kTowardSun), view = local(pixels[k].normal, Vec3::UnitZ());
    principled.push_back(principled_brdf_cosine_weighted(parameters, light, view));
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
  const double worst_exact =
      compare(rings(pixels, principled, exact,
                    [](const Pixel& pixel) { return std::acos(std::clamp(pixel.normal.dot(kTowardSun), -1.0, 1.0)); }),
              (preset + ", sun").c_str());
  std::printf("  %s sun: the render against the exact material, worst ring %.1f%%\n", preset.c_str(),
              100.0 * worst_exact);
}

// The preview scene as exported renders to a file with Blender's own command line, as docs/examples/blender says
// (shrunk to 10% and 4 samples for the test).
TEST_F(BlenderRender, ThePreviewSceneRendersFromTheCommandLine) {
  const std::string script = path("wax.py");
  ASSERT_EQ(run_skinlayer({"export", "--format", "blender", "--scene", "--preset", "wax", "-o", script}).exit_code, 0);
  const ProcessResult rendered = run_process(
      {"blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python", script, "--python-expr",
       "import bpy; scene = bpy.context.scene; scene.render.resolution_percentage = 10; scene.cycles.samples = 4", "-o",
       path("preview_####"), "-F", "PNG", "-f", "1"});
  EXPECT_EQ(rendered.exit_code, 0) << rendered.err;
  EXPECT_EQ(rendered.out.find("Error"), std::string::npos) << rendered.out;
  EXPECT_TRUE(std::filesystem::exists(path("preview_0001.png"))) << rendered.out;
}

// Skin's fit uses the diffuse, sheen and specular lobes; the clear coat's adds Cycles' clearcoat.
TEST_F(BlenderRender, SkinUnderAWhiteFurnaceIsSkinlayersPrincipled) { check_furnace(*this, "skin-fair"); }
TEST_F(BlenderRender, SkinUnderTheSunIsSkinlayersPrincipled) { check_sun(*this, "skin-fair"); }
TEST_F(BlenderRender, ClearCoatUnderTheSunIsSkinlayersPrincipled) { check_sun(*this, "clear-coat-red"); }
// Jade's fit takes a clearcoat of 1 too: under the sun the render is the node skinlayer models.
TEST_F(BlenderRender, JadeUnderTheSunIsSkinlayersPrincipled) { check_sun(*this, "jade"); }
// Not checked: a clearcoat under a furnace or any environment. Cycles 3.4 samples the clearcoat's half vectors from
// GGX's visible normals but takes their density as GTR1's (closure/bsdf_microfacet.h, the GGX sample function), so
// its multiple importance sampling converges to something else than the BSDF it evaluates: clear-coat-red's fit
// renders 0.7-3% darker in red and 7-9% brighter in green and blue than its own BSDF's albedo (measured; under a
// sun, where only the evaluation counts, it is exact). docs/examples/blender/README.md says so.

}  // namespace
}  // namespace skinlayer::test
