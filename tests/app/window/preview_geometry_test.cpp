// The previewer's CPU side: the layout of the window, the sphere's light picking, the lobe plot's value under the
// mouse (which must agree with the CPU model the plot is tested against), and the value state's defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "app/preview/lobe_probe.h"
#include "app/preview/preview_state.h"
#include "app/preview/solve_worker.h"
#include "app/preview/view_layout.h"
#include "core/conventions.h"
#include "core/material.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

TEST(PreviewLayout, PanelAndViewsTileTheWindow) {
  const PreviewLayout both = layout_preview(1280.0f, 720.0f, 390.0f, ViewKind::Both);
  EXPECT_EQ(both.panel.width, 390.0f);
  EXPECT_EQ(both.sphere.x, 390.0f);
  EXPECT_EQ(both.sphere.x + both.sphere.width, both.plots.x);
  EXPECT_EQ(both.plots.x + both.plots.width, 1280.0f);
  EXPECT_EQ(both.sphere.height, 720.0f);
  EXPECT_TRUE(layout_preview(1280.0f, 720.0f, 390.0f, ViewKind::Sphere).plots.empty());
  EXPECT_TRUE(layout_preview(1280.0f, 720.0f, 390.0f, ViewKind::Polar).sphere.empty());
  EXPECT_EQ(layout_preview(600.0f, 400.0f, 390.0f, ViewKind::Both).panel.width, 300.0f);  // at most half
}

TEST(PreviewLayout, CompareShowsThreeSpheresSideBySide) {
  const PreviewLayout compare = layout_preview(1280.0f, 720.0f, 380.0f, ViewKind::Compare);
  EXPECT_TRUE(compare.sphere.empty());
  EXPECT_TRUE(compare.plots.empty());
  EXPECT_FLOAT_EQ(compare.compare[0].x, 380.0f);
  for (int k = 0; k < 2; ++k) EXPECT_FLOAT_EQ(compare.compare[k].x + compare.compare[k].width, compare.compare[k + 1].x);
  EXPECT_FLOAT_EQ(compare.compare[2].x + compare.compare[2].width, 1280.0f);
  EXPECT_TRUE(layout_preview(1280.0f, 720.0f, 380.0f, ViewKind::Both).compare[0].empty());
  // The comparison flag is part of the request, so switching to the compare view solves the other models.
  PreviewState state;
  const SolveRequest plain = solve_request(state);
  state.view.view = ViewKind::Compare;
  EXPECT_FALSE(same_request(plain, solve_request(state)));
  EXPECT_TRUE(solve_request(state).compare);
  EXPECT_EQ(needed_models(solve_request(state)), (std::array<bool, 3>{true, true, true}));
}

// The plots may show another model than the sphere: both are solved, nothing more.
TEST(PreviewState, PlotsCanShowAnotherModelThanTheSphere) {
  PreviewState state;
  EXPECT_EQ(solve_request(state).plot_model, SubsurfaceModel::Stam);
  EXPECT_EQ(needed_models(solve_request(state)), (std::array<bool, 3>{true, false, false}));
  state.view.plot_model = SubsurfaceModel::HanrahanKrueger;
  const SolveRequest request = solve_request(state);
  EXPECT_EQ(request.material.model, SubsurfaceModel::Stam);
  EXPECT_EQ(request.plot_model, SubsurfaceModel::HanrahanKrueger);
  EXPECT_EQ(needed_models(request), (std::array<bool, 3>{true, false, true}));
  const SolveResult result = compute_solve(request, 1);
  ASSERT_TRUE(result.error.empty()) << result.error;
  ASSERT_TRUE(result.by_model[2].has_value());
  EXPECT_FALSE(result.by_model[1].has_value());
  // The plots' tables are Hanrahan-Krueger's: far less reflection than the layer's.
  EXPECT_LT(result.by_model[2]->channels[0].brdf_subsurface(0.5, 0.5, 3.0),
            0.5 * result.tables().channels[0].brdf_subsurface(0.5, 0.5, 3.0));
}

TEST(PreviewLayout, ViewportsAreInFramebufferPixelsFromTheBottom) {
  const Rect rect{100.0f, 50.0f, 200.0f, 100.0f};
  const Viewport plain = to_viewport(rect, {1.0f, 1.0f}, 720);
  EXPECT_EQ(plain.x, 100);
  EXPECT_EQ(plain.y, 720 - 150);
  EXPECT_EQ(plain.width, 200);
  EXPECT_EQ(plain.height, 100);
  const Viewport retina = to_viewport(rect, {2.0f, 2.0f}, 1440);
  EXPECT_EQ(retina.x, 200);
  EXPECT_EQ(retina.y, 1440 - 300);
  EXPECT_EQ(retina.width, 400);
  EXPECT_EQ(retina.height, 200);
}

TEST(PreviewLayout, WindowAndViewPointsAreInverse) {
  const Rect rect{390.0f, 0.0f, 445.0f, 720.0f};
  const std::array<float, 2> p = window_point(rect, Renderer::kLobeMargin, 0.3, -0.7);
  const std::array<double, 2> back = view_point(rect, Renderer::kLobeMargin, p[0], p[1]);
  EXPECT_NEAR(back[0], 0.3, 1e-5);
  EXPECT_NEAR(back[1], -0.7, 1e-5);
  // The unit circle fits the shorter side with the renderer's margin, as view_extent() has it.
  EXPECT_FLOAT_EQ(pixels_per_unit(rect, Renderer::kLobeMargin), static_cast<float>(445.0 / (2.0 * 1.1)));
}

TEST(SphereLight, DraggingToALightsPointGivesThatLight) {
  const Rect sphere{390.0f, 0.0f, 445.0f, 720.0f};
  for (const LightAngles light : {LightAngles{0.4, 2.0}, LightAngles{1.2, -0.5}, LightAngles{0.8, kPi}}) {
    const std::array<float, 2> p = sphere_point_of_light(sphere, light);
    const LightAngles picked = light_from_sphere_point(sphere, p[0], p[1], degrees_to_radians(89.9));
    EXPECT_NEAR(picked.theta, light.theta, 1e-4);
    EXPECT_NEAR(std::remainder(picked.phi - light.phi, 2.0 * kPi), 0.0, 1e-4);
    // The picked light is the sphere's normal at that point: the light direction (light_direction() in scene.h:
    // sin(theta) cos(phi), sin(theta) sin(phi), cos(theta)) projects onto the point's view coordinates.
    const std::array<double, 2> v = view_point(sphere, Renderer::kSphereMargin, p[0], p[1]);
    EXPECT_NEAR(std::sin(picked.theta) * std::cos(picked.phi), v[0], 1e-4);
    EXPECT_NEAR(std::sin(picked.theta) * std::sin(picked.phi), v[1], 1e-4);
  }
  // Off the sphere: on the rim, limited to the largest light angle.
  const LightAngles rim = light_from_sphere_point(sphere, sphere.x + sphere.width - 1.0f, 360.0f, 1.5);
  EXPECT_DOUBLE_EQ(rim.theta, 1.5);
  EXPECT_NEAR(rim.phi, 0.0, 1e-6);
}

class LobeProbe : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ColorMaterial material;
    material.albedo_rgb = {0.9, 0.7, 0.5};
    tables_ = solve_color(material, 0.5);
  }
  static void TearDownTestSuite() { tables_.reset(); }
  static const ColorTables& tables() { return *tables_; }

 private:
  static inline std::optional<ColorTables> tables_;
};

TEST_F(LobeProbe, AboveTheLineIsTheBrdfAndBelowTheBtdf) {
  const double theta_i = 0.6;
  // Up and to the right: reflection, forward side (phi = pi), theta_o = atan(x / y).
  const LobeSample forward = probe_lobe(tables(), theta_i, 0.3, 0.4);
  EXPECT_TRUE(forward.reflection);
  EXPECT_DOUBLE_EQ(forward.phi, kPi);
  EXPECT_NEAR(forward.theta_o, std::atan2(0.3, 0.4), 1e-12);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(forward.total[c], brdf_total(tables(), c, theta_i, forward.theta_o, kPi));
  }
  EXPECT_EQ(forward.surface, brdf_surface(tables().material.layer, theta_i, forward.theta_o, kPi));
  EXPECT_GT(forward.plotted_subsurface(), 0.0);

  // Down and to the left: transmission, back side (phi = 0).
  const LobeSample back = probe_lobe(tables(), theta_i, -0.2, -0.5);
  EXPECT_FALSE(back.reflection);
  EXPECT_DOUBLE_EQ(back.phi, 0.0);
  EXPECT_EQ(back.surface, 0.0);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(back.total[c], btdf_total(tables(), c, theta_i, back.theta_o, 0.0));
  // Red has the highest albedo: it scatters most.
  EXPECT_GT(back.total[0], back.total[2]);
}

TEST(LobeScale, RadiusAndRingValueAreInverse) {
  LobeView linear;
  linear.peak = 2.5;
  EXPECT_DOUBLE_EQ(lobe_radius(linear, 2.5), 1.0);
  EXPECT_DOUBLE_EQ(lobe_value_at_radius(linear, 0.5), 1.25);
  LobeView log = linear;
  log.log_scale = true;
  log.decades = 3.0;
  EXPECT_DOUBLE_EQ(lobe_radius(log, 2.5), 1.0);
  EXPECT_NEAR(lobe_radius(log, 2.5e-3), 0.0, 1e-12);
  EXPECT_EQ(lobe_radius(log, 1e-9), 0.0);
  for (double r : {0.25, 0.5, 0.75}) EXPECT_NEAR(lobe_radius(log, lobe_value_at_radius(log, r)), r, 1e-12);
}

TEST(PreviewState, TheDefaultIsThePapersMaterial) {
  const ColorMaterial material = paper_default_material();
  EXPECT_EQ(material.layer.sigma, parameter_info("sigma").default_value);
  EXPECT_EQ(material.layer.eta, parameter_info("eta").default_value);
  EXPECT_NEAR(material.layer.transparency(), 0.2, 1e-15);
  EXPECT_EQ(material.layer.g, 0.8);
  EXPECT_EQ(material.albedo_rgb, (std::array<double, 3>{1.0, 1.0, 1.0}));
  EXPECT_EQ(material.layer.bottom.kind, BottomKind::Air);
  EXPECT_FALSE(material.layer.ordinates.has_value());
  EXPECT_TRUE(same_request(SolveRequest{material, 0.0}, SolveRequest{ColorMaterial{}, 0.0}));
}

TEST(PreviewState, ResetKeepsLightAndViewAndMakesTheSameRequestAsNew) {
  PreviewState state;
  state.material.layer.sigma = 0.2;
  state.material.albedo_rgb = {0.5, 0.4, 0.3};
  state.material.layer.bottom.kind = BottomKind::Lambert;
  state.light.theta_degrees = 30.0;
  state.view.exposure_stops = 2.0;
  const PreviewState reset = reset_material(state);
  EXPECT_EQ(reset.light.theta_degrees, 30.0);
  EXPECT_EQ(reset.view.exposure_stops, 2.0);
  PreviewState fresh;
  fresh.light.theta_degrees = 30.0;
  EXPECT_TRUE(same_request(solve_request(reset), solve_request(fresh)));
  EXPECT_FALSE(same_request(solve_request(state), solve_request(fresh)));
  EXPECT_DOUBLE_EQ(solve_request(fresh).theta_i, degrees_to_radians(30.0));
  EXPECT_DOUBLE_EQ(exposure_multiplier(reset.view), 4.0);
}

}  // namespace
}  // namespace skinlayer
