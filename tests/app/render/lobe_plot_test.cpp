// The polar lobe plot as the GPU draws it, against the CPU evaluation: along rays in the plane of incidence the
// plotted radius of the total lobe equals f / peak (linear) or 1 + log10(f / peak) / decades (log), with f from
// core's BRDF and the solver's tables; and in the picture the filled lobe ends where that radius says.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "app/gl/osmesa_context.h"
#include "app/render/render_target.h"
#include "app/render/renderer.h"
#include "app/render/scene.h"
#include "app/render/table_textures.h"
#include "app/solution/material_solve.h"
#include "core/conventions.h"

namespace skinlayer {
namespace {

constexpr int kSize = 400;

double cpu_lobe_value(const ColorTables& tables, double theta_i, double angle_from_up) {
  const bool reflection = std::abs(angle_from_up) < 0.5 * kPi;
  const double theta_o = reflection ? std::abs(angle_from_up) : kPi - std::abs(angle_from_up);
  const double phi = angle_from_up >= 0.0 ? kPi : 0.0;  // right side = forward
  double f = 0.0;
  for (int c = 0; c < 3; ++c) {
    f += (reflection ? brdf_total(tables, c, theta_i, theta_o, phi) : btdf_total(tables, c, theta_i, theta_o, phi)) / 3;
  }
  return f;
}

// The pixel (x right, y down from the top) at plot radius r along a ray at `angle` from the upward normal.
std::array<int, 2> pixel_at(double angle, double r) {
  const std::array<double, 2> extent = view_extent({0, 0, kSize, kSize}, Renderer::kLobeMargin);
  const double px = r * std::sin(angle), py = r * std::cos(angle);
  return {static_cast<int>((px / extent[0] + 1.0) * 0.5 * kSize),
          static_cast<int>((1.0 - py / extent[1]) * 0.5 * kSize)};
}

// The lobe plot of `tables` (uploaded to the renderer, whose context is current) at theta_i drawn offscreen into a
// float target: the scene and the (total radius, subsurface radius, pixel radius) texels.
struct LobeRender {
  Scene scene;
  std::vector<float> radii;
};
LobeRender render_lobe_radii(const Renderer& renderer, const ColorTables& tables, double theta_i, bool log_scale) {
  LobeRender result{make_scene(tables, ViewKind::Polar, theta_i, 0.0, 1.0, log_scale), {}};
  result.scene.lobes.linear_output = true;
  RenderTarget target(kSize, kSize, PixelFormat::Rgba32F);
  target.bind();
  draw_scene(renderer, result.scene, kSize, kSize);
  RenderTarget::unbind();
  result.radii = target.read_rgba32f();
  return result;
}

class LobePlot : public ::testing::TestWithParam<bool> {};

TEST_P(LobePlot, RadiusAlongRaysMatchesCpu) {
  const bool log_scale = GetParam();
  ColorMaterial material;
  material.layer.tau = optical_depth_from_transparency(0.3);
  const double theta_i = degrees_to_radians(50.0);
  const ColorTables tables = solve_color(material, theta_i);
  gl::OsmesaContext context(kSize, kSize);
  Renderer renderer;
  renderer.upload(make_table_textures(tables));
  LobeRender lobes = render_lobe_radii(renderer, tables, theta_i, log_scale);
  Scene& scene = lobes.scene;
  const std::vector<float>& radii = lobes.radii;
  int checked = 0;
  for (double degrees : {-80.0, -45.0, -10.0, 20.0, 50.0, 75.0, 110.0, 150.0, 170.0, -150.0}) {
    const double angle = degrees_to_radians(degrees);
    const double f = cpu_lobe_value(tables, theta_i, angle);
    double expected = f / scene.lobes.peak;
    if (log_scale) expected = std::max(0.0, 1.0 + std::log10(f / scene.lobes.peak) / scene.lobes.decades);
    const auto [x, y] = pixel_at(angle, 0.6);
    const float gpu = radii[(static_cast<std::size_t>(y) * kSize + x) * 4];
    // The pixel centre lies within half a pixel of the ray; allow for that angular offset and float evaluation.
    EXPECT_NEAR(gpu, expected, 1e-2 * expected + 2e-3) << "ray at " << degrees << " degrees";
    ++checked;
  }
  EXPECT_EQ(checked, 10);

  // The drawn picture: along each ray the lobe fill ends within two pixels of the CPU radius.
  scene.lobes.linear_output = false;
  RenderTarget picture(kSize, kSize, PixelFormat::Rgba8);
  picture.bind();
  draw_scene(renderer, scene, kSize, kSize);
  RenderTarget::unbind();
  const std::vector<std::uint8_t> rgba = picture.read_rgba8();
  const std::array<double, 2> extent = view_extent({0, 0, kSize, kSize}, Renderer::kLobeMargin);
  const double pixel = 2.0 * extent[0] / kSize;
  for (double degrees : {-60.0, 30.0, 65.0, 135.0}) {
    const double angle = degrees_to_radians(degrees);
    const double f = cpu_lobe_value(tables, theta_i, angle);
    const double expected =
        log_scale ? std::max(0.0, 1.0 + std::log10(f / scene.lobes.peak) / scene.lobes.decades) : f / scene.lobes.peak;
    if (expected < 0.1) continue;
    double last_filled = 0.0;
    for (double r = 0.02; r < 1.05; r += 0.25 * pixel) {
      const auto [x, y] = pixel_at(angle, r);
      const std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * kSize + x) * 4];
      const bool background = std::abs(p[0] - p[2]) < 40 && std::abs(p[0] - p[1]) < 40;  // grey grid or backdrop
      if (!background) last_filled = r;
    }
    EXPECT_NEAR(last_filled, expected, 2.5 * pixel) << "ray at " << degrees << " degrees";
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, LobePlot, ::testing::Values(false, true));

// Sharp refraction lobes, narrower than the tables' grid: the GPU adds the unscattered part from its in-plane
// texture, and must agree with the CPU's exact evaluation at every pixel across the lobe, the peak included. Each
// pixel is judged at its own centre's angle (a pixel spans ~0.5 degree here, half the lobe's width).
TEST(LobePlotSharp, EveryPixelAcrossTheUnscatteredLobeMatchesCpu) {
  struct Case {
    double sigma, transparency, albedo;
    BottomKind bottom;
    double theta_i_deg, exit_deg;  // the lobe's flat-interface exit angle (forward side)
  };
  const Case cases[] = {
      {0.05, 0.2, 0.0, BottomKind::Matched, 30.0, 20.92},  // one interface: into the index-matched medium
      {0.1, 0.5, 0.5, BottomKind::Air, 30.0, 30.0},        // two interfaces, air on both sides
  };
  for (const Case& c : cases) {
    ColorMaterial material;
    material.layer.sigma = c.sigma;
    material.layer.tau = optical_depth_from_transparency(c.transparency);
    material.layer.bottom.kind = c.bottom;
    material.albedo_rgb = {c.albedo, c.albedo, c.albedo};
    const double theta_i = degrees_to_radians(c.theta_i_deg);
    const ColorTables tables = solve_color(material, theta_i);
    gl::OsmesaContext context(kSize, kSize);
    Renderer renderer;
    renderer.upload(make_table_textures(tables));
    const LobeRender lobes = render_lobe_radii(renderer, tables, theta_i, false);
    const Scene& scene = lobes.scene;
    const std::vector<float>& radii = lobes.radii;
    const std::array<double, 2> extent = view_extent({0, 0, kSize, kSize}, Renderer::kLobeMargin);
    double largest = 0.0;
    int judged = 0;
    // Pixels along the ray through the lobe's centre at plot radius 0.5, stepping one pixel sideways each.
    const double centre = kPi - degrees_to_radians(c.exit_deg);
    for (int step = -12; step <= 12; ++step) {
      const auto [x, y] = pixel_at(centre + step * 0.0075, 0.5);
      const double px = ((x + 0.5) / kSize * 2.0 - 1.0) * extent[0];
      const double py = (1.0 - (y + 0.5) / kSize * 2.0) * extent[1];
      const double f = cpu_lobe_value(tables, theta_i, std::atan2(px, py));
      largest = std::max(largest, f / scene.lobes.peak);
      const float gpu = radii[(static_cast<std::size_t>(y) * kSize + x) * 4];
      EXPECT_NEAR(gpu, f / scene.lobes.peak, 1e-2 * f / scene.lobes.peak + 2e-3)
          << "sigma " << c.sigma << " pixel " << x << ", " << y;
      ++judged;
    }
    EXPECT_EQ(judged, 25);
    EXPECT_GT(largest, 0.9) << "the pixels must cross the lobe's peak (the plot's largest value)";
  }
}

}  // namespace
}  // namespace skinlayer
