// The sphere as the GPU draws it, against the CPU evaluation of the same radiance.
//
// For each checked pixel the test rebuilds the geometry independently (orthographic view along -z, unit sphere,
// directional light) and evaluates L = (f_surface + f_subsurface) E cos(theta_i) with core's BRDF and the solver's
// spline tables. Tolerance: 0.2% relative (plus 1e-5 absolute for the dark limb). The GPU differs from the CPU by
// float arithmetic (1e-6), the erf approximation in GLSL (1.5e-7 absolute), and mainly by sampling the tables
// bilinearly on a 2x refined grid instead of evaluating the Catmull-Rom spline: that interpolation error is
// O(h^2 f'') with h = 1/94 of the grid's range; measured at most 6.1e-4 relative on the layered materials (the
// surface-only case differs by up to 2.5e-3 of values near the 1e-5 absolute floor, at the dark rim).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

#include "app/gl/osmesa_context.h"
#include "app/render/render_target.h"
#include "app/render/renderer.h"
#include "app/render/scene.h"
#include "app/render/table_textures.h"
#include "app/solution/material_solve.h"
#include "core/conventions.h"
#include "core/interfaces/microfacet.h"
#include "core/spatial/curvature_spread.h"

namespace skinlayer {
namespace {

struct Case {
  ColorMaterial material;
  double light_theta;
  double light_phi;
};

std::vector<Case> cases() {
  ColorMaterial paper;  // the paper's default, white
  ColorMaterial skin;
  skin.layer.sigma = 0.3;
  skin.layer.tau = optical_depth_from_transparency(0.05);
  skin.albedo_rgb = {0.95, 0.7, 0.55};
  ColorMaterial lambert;
  lambert.layer.eta = 1.8;
  lambert.layer.sigma = 0.8;
  lambert.layer.g = 0.2;
  lambert.layer.bottom = parse_bottom("lambert:0.6");
  lambert.albedo_rgb = {0.5, 0.5, 0.9};
  ColorMaterial surface_only;  // no medium and nothing below: the picture is the GLSL surface term alone
  surface_only.layer.tau = 0.0;
  surface_only.layer.sigma = 0.2;
  surface_only.layer.eta = 2.0;
  surface_only.layer.bottom = parse_bottom("matched");
  ColorMaterial spectral;  // a biophysical skin: its channels are weighted sums of 31 wavelengths' tables
  spectral.layer.sigma = 0.35;
  spectral.skin = SkinParameters{};
  spectral.skin->melanin = 0.08;
  return {{paper, degrees_to_radians(45.0), kPi},
          {spectral, degrees_to_radians(40.0), 2.8},
          {skin, degrees_to_radians(30.0), 0.5},
          {lambert, 1.2, 2.0},
          {surface_only, degrees_to_radians(35.0), 2.5}};
}

// The shading geometry of pixel (x, y) (rows top-down) of the sphere view, as shaders/shading.glsl's local_angles:
// the light's cosine and polar angle, the view's polar angle, and the azimuth between them about the normal. Unset off
// the sphere, beyond r^2 = max_r2 of the view's radius.
struct PixelAngles {
  double cos_i, theta_i, theta_o, phi;
};
std::optional<PixelAngles> pixel_angles(const SphereView& view, const Viewport& viewport, int x, int y, double max_r2) {
  const std::array<double, 2> extent = view_extent(viewport, Renderer::kSphereMargin);
  const double px = ((x + 0.5) / viewport.width * 2.0 - 1.0) * extent[0];
  const double py = (1.0 - (y + 0.5) / viewport.height * 2.0) * extent[1];
  const double r2 = px * px + py * py;
  if (r2 > max_r2) return std::nullopt;
  const Vec3 n(px, py, std::sqrt(1.0 - r2));
  const Vec3 l(view.light[0], view.light[1], view.light[2]);
  const Vec3 v(0.0, 0.0, 1.0);
  const double cos_i = std::clamp(n.dot(l), -1.0, 1.0), cos_o = n.dot(v);
  const Vec3 li = (l - cos_i * n).normalized();
  const Vec3 vo = (v - cos_o * n).normalized();
  const double phi = std::acos(std::clamp(li.dot(vo), -1.0, 1.0));
  return PixelAngles{cos_i, std::acos(cos_i), std::acos(cos_o), phi};
}

// The CPU radiance of one pixel (rows top-down), or a negative value off the sphere / in shadow.
std::array<double, 3> cpu_radiance(const ColorTables& tables, const SphereView& view, const Viewport& viewport, int x,
                                   int y, bool& lit) {
  const std::optional<PixelAngles> a = pixel_angles(view, viewport, x, y, 0.98);
  lit = a && a->cos_i >= 0.05;
  if (!lit) return {};
  std::array<double, 3> radiance{};
  for (int c = 0; c < 3; ++c) {
    radiance[c] = brdf_total(tables, c, a->theta_i, a->theta_o, a->phi) * view.irradiance * a->cos_i;
  }
  return radiance;
}

TEST(SpherePixels, MatchTheCpuRadiance) {
  const int size = 160;
  gl::OsmesaContext context(size, size);
  Renderer renderer;
  RenderTarget target(size, size, PixelFormat::Rgba32F);
  for (const Case& c : cases()) {
    const ColorTables tables = solve_color(c.material, c.light_theta);
    renderer.upload(make_table_textures(tables));
    Scene scene = make_scene(tables, ViewKind::Sphere, c.light_theta, c.light_phi, 1.0, false);
    scene.sphere.linear_output = true;
    target.bind();
    draw_scene(renderer, scene, size, size);
    RenderTarget::unbind();
    const std::vector<float> pixels = target.read_rgba32f();
    int checked = 0;
    double worst = 0.0;
    for (int y = 3; y < size; y += 7) {
      for (int x = 5; x < size; x += 7) {
        bool lit = false;
        const std::array<double, 3> expected =
            cpu_radiance(tables, scene.sphere, {0, 0, size, size}, x, y, lit);
        if (!lit) continue;
        for (int ch = 0; ch < 3; ++ch) {
          const double gpu = pixels[(static_cast<std::size_t>(y) * size + x) * 4 + ch];
          const double error = std::abs(gpu - expected[ch]);
          worst = std::max(worst, error / (expected[ch] + 1e-5));
          // 2e-5 absolute: float textures of the top's multiply scattered lobe near grazing (1.6e-5 at worst).
          EXPECT_LT(error, 2e-3 * expected[ch] + 2e-5) << "pixel " << x << "," << y << " channel " << ch;
        }
        ++checked;
      }
    }
    EXPECT_GE(checked, 50);
    RecordProperty("worst_relative_error", std::to_string(worst));
    std::printf("sphere case: %d pixels, worst relative error %.2e\n", checked, worst);
  }
}

// The subsurface term spread by a profile (shaders/shading.glsl, spread_radiance) against the same convolution on the
// CPU: core's CurvatureSpread evaluated at each pixel's angle from the light, where the GPU interpolates its 256
// samples. A weakly absorbing half-space under a rough top, with a profile per channel 0.5, 2 and 6 mm wide on a
// sphere of 10 mm: the light reaches past the terminator, more in the wider channels, and the pixels there are
// checked too. Tolerance as above, plus the texture's interpolation (2e-5 relative of the spread).
TEST(SpherePixels, SpreadSubsurfaceMatchesTheCpuConvolution) {
  const int size = 160;
  gl::OsmesaContext context(size, size);
  Renderer renderer;
  RenderTarget target(size, size, PixelFormat::Rgba32F);
  ColorMaterial material;
  material.layer.sigma = 0.4;
  material.layer.tau = std::numeric_limits<double>::infinity();
  material.albedo_rgb = {0.99, 0.9, 0.7};
  const double light_theta = degrees_to_radians(70.0), light_phi = kPi;
  const ColorTables tables = solve_color(material, light_theta);
  renderer.upload(make_table_textures(tables));
  std::vector<double> edges = {0.0};
  for (int i = 0; i < 80; ++i) edges.push_back(1e-3 * std::pow(3e4, i / 79.0));
  std::vector<CurvatureSpread> spreads;
  std::vector<float> texels(256 * 3);
  const double widths[] = {0.5, 2.0, 6.0};
  for (int c = 0; c < 3; ++c) {
    std::vector<double> powers;
    for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
      const auto mass = [&](double r) { return -(r + widths[c]) * std::exp(-r / widths[c]); };
      powers.push_back(mass(edges[i + 1]) - mass(edges[i]));
    }
    spreads.emplace_back(edges, powers, 10.0);
    const std::vector<double> samples = spreads.back().sampled(256);
    for (int k = 0; k < 256; ++k) texels[static_cast<std::size_t>(3 * k + c)] = static_cast<float>(samples[k]);
  }
  renderer.upload_spread(texels);
  Scene scene = make_scene(tables, ViewKind::Sphere, light_theta, light_phi, 1.0, false);
  scene.sphere.linear_output = true;
  scene.sphere.spread = true;
  target.bind();
  draw_scene(renderer, scene, size, size);
  RenderTarget::unbind();
  const std::vector<float> pixels = target.read_rgba32f();
  int checked = 0, past_terminator = 0;
  for (int y = 3; y < size; y += 7) {
    for (int x = 5; x < size; x += 7) {
      const std::optional<PixelAngles> a = pixel_angles(scene.sphere, {0, 0, size, size}, x, y, 0.95);
      if (!a) continue;
      const auto [cos_i, theta_i, theta_o, phi] = *a;
      const double surface = cos_i > 0.0 ? brdf_surface(tables.material.layer, theta_i, theta_o, phi) * cos_i : 0.0;
      for (int c = 0; c < 3; ++c) {
        // The unscattered light (here the top's multiply scattered reflection) leaves where the light falls, as the
        // surface term does; the scattered light is spread.
        const LayerTables& channel = tables.channels[static_cast<std::size_t>(c)];
        const double scattered = channel.brdf_scattered(std::min(theta_i, kSpreadMaxTheta), theta_o, phi);
        const double unscattered =
            cos_i > 0.0 ? channel.unscattered().brdf(theta_i, theta_o, phi) * cos_i : 0.0;
        const double expected =
            (surface + unscattered + scattered * spreads[static_cast<std::size_t>(c)](theta_i)) *
            scene.sphere.irradiance;
        const double gpu = pixels[(static_cast<std::size_t>(y) * size + x) * 4 + static_cast<std::size_t>(c)];
        EXPECT_NEAR(gpu, expected, 2e-3 * expected + 2e-5) << "pixel " << x << "," << y << " channel " << c;
      }
      ++checked;
      if (cos_i < 0.0) ++past_terminator;
    }
  }
  EXPECT_GE(checked, 200);
  EXPECT_GE(past_terminator, 30);
  std::printf("spread sphere: %d pixels, %d past the terminator\n", checked, past_terminator);
}

}  // namespace
}  // namespace skinlayer
