// The A/B comparison as the GPU draws it (Renderer::draw_split_sphere, LobeView::outline): left of the split line
// the sphere is exactly A's picture and right of it exactly B's, under the same light; B's lobe outline lies where
// B's own plotted radius is, and leaves A's plot untouched elsewhere.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "app/gl/osmesa_context.h"
#include "app/render/render_target.h"
#include "app/render/renderer.h"
#include "app/render/scene.h"
#include "app/render/table_textures.h"
#include "app/solution/material_solve.h"

namespace skinlayer {
namespace {

constexpr int kSize = 120;

// The float pixels of what draw() draws into the target, cleared first.
template <class Draw>
std::vector<float> drawn(const RenderTarget& target, const Draw& draw) {
  target.bind();
  glClear(GL_COLOR_BUFFER_BIT);
  draw();
  RenderTarget::unbind();
  return target.read_rgba32f();
}

TEST(AbComparison, TheSplitSphereIsAOnTheLeftAndBOnTheRight) {
  gl::OsmesaContext context(kSize, kSize);
  Renderer renderer;
  ColorMaterial a;
  a.albedo_rgb = {0.4, 0.3, 0.2};
  a.layer.g = 0.2;
  ColorMaterial b;  // the paper's default
  b.layer.sigma = 0.3;
  const ColorTables tables_a = solve_color(a, 0.785), tables_b = solve_color(b, 0.785);
  renderer.upload(make_table_textures(tables_a), 0);
  renderer.upload(make_table_textures(tables_b), Renderer::kPinnedSlot);
  Scene scene = make_scene(tables_a, ViewKind::Sphere, 0.785, 3.14159, 1.0, false);
  scene.sphere.linear_output = true;
  const SurfaceParams surface_a{a.layer.eta, a.layer.sigma}, surface_b{b.layer.eta, b.layer.sigma};
  const Viewport viewport{0, 0, kSize, kSize};
  RenderTarget target(kSize, kSize, PixelFormat::Rgba32F);
  const auto draw = [&](const auto& how) { return drawn(target, how); };
  const std::vector<float> only_a = draw([&] { renderer.draw_sphere(scene.sphere, surface_a, viewport, 0); });
  const std::vector<float> only_b =
      draw([&] { renderer.draw_sphere(scene.sphere, surface_b, viewport, Renderer::kPinnedSlot); });
  constexpr double kSplit = 0.4;
  const std::vector<float> split = draw([&] {
    renderer.draw_split_sphere(scene.sphere, {surface_a, surface_b}, {0, Renderer::kPinnedSlot}, {nullptr, nullptr},
                               viewport, kSplit);
  });
  const int line = static_cast<int>(std::lround(kSplit * kSize));
  int left = 0, right = 0, differing = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      if (x >= line - 1 && x <= line) continue;  // the line itself
      const std::size_t at = (static_cast<std::size_t>(y) * kSize + x) * 4;
      const std::vector<float>& expected = x < line ? only_a : only_b;
      for (int c = 0; c < 3; ++c) ASSERT_EQ(split[at + c], expected[at + c]) << x << "," << y << " channel " << c;
      (x < line ? left : right) += 1;
      differing += only_a[at] != only_b[at] ? 1 : 0;
    }
  }
  EXPECT_GT(left, 0);
  EXPECT_GT(right, 0);
  EXPECT_GT(differing, kSize * kSize / 10) << "the two materials must look different for this test to mean much";
}

TEST(AbComparison, TheOutlineOfBLiesOnBsLobeAndChangesNothingElse) {
  constexpr int kPlot = 300;
  gl::OsmesaContext context(kPlot, kPlot);
  Renderer renderer;
  ColorMaterial a;
  a.albedo_rgb = {0.5, 0.5, 0.5};
  ColorMaterial b;
  b.layer.sigma = 0.3;
  b.layer.g = 0.5;
  const ColorTables tables_a = solve_color(a, 0.785), tables_b = solve_color(b, 0.785);
  renderer.upload(make_table_textures(tables_a), 0);
  renderer.upload(make_table_textures(tables_b), Renderer::kPinnedSlot);
  const Scene scene_a = make_scene(tables_a, ViewKind::Polar, 0.785, 3.14159, 1.0, false);
  LobeView lobes_b = make_scene(tables_b, ViewKind::Polar, 0.785, 3.14159, 1.0, false).lobes;
  lobes_b.peak = scene_a.lobes.peak;  // in A's scale
  const SurfaceParams surface_a{a.layer.eta, a.layer.sigma}, surface_b{b.layer.eta, b.layer.sigma};
  const Viewport viewport{0, 0, kPlot, kPlot};
  RenderTarget target(kPlot, kPlot, PixelFormat::Rgba32F);
  const auto draw = [&](const auto& how) { return drawn(target, how); };
  const std::vector<float> plain = draw([&] { renderer.draw_lobes(scene_a.lobes, surface_a, viewport, 0); });
  LobeView outline = lobes_b;
  outline.outline = true;
  const std::vector<float> with_b = draw([&] {
    renderer.draw_lobes(scene_a.lobes, surface_a, viewport, 0);
    renderer.draw_lobes(outline, surface_b, viewport, Renderer::kPinnedSlot);
  });
  LobeView radius = lobes_b;  // B's plotted total radius per pixel (R) and the pixel's own radius (B)
  radius.linear_output = true;
  const std::vector<float> radii =
      draw([&] { renderer.draw_lobes(radius, surface_b, viewport, Renderer::kPinnedSlot); });
  const double pixel = 2.0 * view_extent(viewport, Renderer::kLobeMargin)[0] / kPlot;
  int changed = 0;
  for (std::size_t k = 0; k < plain.size(); k += 4) {
    if (with_b[k] == plain[k] && with_b[k + 1] == plain[k + 1] && with_b[k + 2] == plain[k + 2]) continue;
    ++changed;
    const double r_lobe = radii[k], r_pixel = radii[k + 2];
    EXPECT_LE(std::abs(r_pixel - r_lobe), 2.0 * pixel) << "an outline pixel away from B's lobe, pixel " << k / 4;
    EXPECT_NEAR(with_b[k], 0.95, 1e-6);
  }
  EXPECT_GT(changed, 200) << "the outline is drawn";
}

}  // namespace
}  // namespace skinlayer
