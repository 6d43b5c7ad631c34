#include "app/render/scene.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "app/gl/gl_api.h"
#include "app/process/parallel_for.h"
#include "core/conventions.h"

namespace skinlayer {

namespace {

// Each view's name on the command line and in the pictures' metadata, in ViewKind order.
constexpr std::array<std::string_view, 4> kViewKindNames = {"sphere", "polar", "both", "compare"};

}  // namespace

std::optional<ViewKind> parse_view_kind(std::string_view name) {
  const auto found = std::find(kViewKindNames.begin(), kViewKindNames.end(), name);
  if (found == kViewKindNames.end()) return std::nullopt;
  return static_cast<ViewKind>(found - kViewKindNames.begin());
}

std::string_view view_kind_name(ViewKind view) { return kViewKindNames[static_cast<std::size_t>(view)]; }

glm::dvec3 light_direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

Scene make_scene(const ColorTables& tables, ViewKind view, double light_theta, double light_phi, double exposure,
                 bool log_scale, const Scene* previous) {
  Scene scene;
  scene.view = view;
  scene.surface = {tables.material.layer.eta, tables.material.layer.sigma, tables.material.layer.microfacet};
  scene.sphere.light = light_direction(light_theta, light_phi);
  scene.sphere.exposure = exposure;
  scene.lobes.theta_i = light_theta;
  scene.lobes.log_scale = log_scale;
  scene.lobes.unscattered = sample_unscattered_plane(tables.channels[0].unscattered(), light_theta, 128,
                                                     previous ? &previous->lobes.unscattered : nullptr);
  // The peak over the plot: every half degree, and every sample of the unscattered lobe (which can be narrower).
  // The BTDF is the tables' scattered part plus the sampled unscattered part, as the lobe shader adds them.
  std::vector<double> signed_angles;
  for (int k = -180; k <= 180; ++k) signed_angles.push_back(0.5 * kPi * k / 180.0);
  for (std::size_t k = 0; k < scene.lobes.unscattered.btdf.size(); ++k) {
    signed_angles.push_back(unscattered_plane_angle(scene.lobes.unscattered, k));
  }
  // The scan in two halves side by side (the channels' table evaluations are most of a slider step's CPU time here).
  std::array<double, 2> half_peaks{};
  const std::size_t half = signed_angles.size() / 2;
  const UnscatteredLight& unscattered = tables.channels[0].unscattered();
  parallel_for_threads(2, [&](int part) {
    const std::size_t begin = part == 0 ? 0 : half, end = part == 0 ? half : signed_angles.size();
    double peak = 0.0;
    for (std::size_t k = begin; k < end; ++k) {
      const double s = signed_angles[k];
      const double theta_o = std::abs(s);
      const double phi = s >= 0.0 ? kPi : 0.0;
      double reflected =
          brdf_surface(tables.material.layer, light_theta, theta_o, phi) + unscattered.brdf(light_theta, theta_o, phi);
      double transmitted = unscattered_plane_value(scene.lobes.unscattered, s);
      for (int c = 0; c < 3; ++c) {
        reflected += tables.channels[c].brdf_scattered(light_theta, theta_o, phi) / 3.0;
        transmitted += tables.channels[c].btdf_scattered(light_theta, theta_o, phi) / 3.0;
      }
      peak = std::max({peak, reflected, transmitted});
    }
    half_peaks[static_cast<std::size_t>(part)] = peak;
  });
  const double peak = std::max(half_peaks[0], half_peaks[1]);
  scene.lobes.peak = peak > 0.0 ? peak : 1.0;
  return scene;
}

std::vector<Viewport> scene_viewports(ViewKind view, int width, int height) {
  if (view == ViewKind::Compare) {
    const int third = width / 3;
    return {{0, 0, third, height}, {third, 0, third, height}, {2 * third, 0, width - 2 * third, height}};
  }
  if (view != ViewKind::Both) return {{0, 0, width, height}};
  const int half = width / 2;
  return {{0, 0, half, height}, {half, 0, width - half, height}};
}

void draw_scene(const Renderer& renderer, const Scene& scene, int width, int height,
                const EnvironmentAccumulation* environment) {
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glClearColor(kFlatBackdrop[0], kFlatBackdrop[1], kFlatBackdrop[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const std::vector<Viewport> viewports = scene_viewports(scene.view, width, height);
  if (scene.view == ViewKind::Sphere) renderer.draw_sphere(scene.sphere, scene.surface, viewports[0], 0, environment);
  if (scene.view == ViewKind::Polar) renderer.draw_lobes(scene.lobes, scene.surface, viewports[0]);
  if (scene.view == ViewKind::Both) {
    renderer.draw_sphere(scene.sphere, scene.surface, viewports[0], 0, environment);
    renderer.draw_lobes(scene.lobes, scene.surface, viewports[1]);
  }
  if (scene.view == ViewKind::Compare) {
    for (std::size_t k = 0; k < kCompareSlots.size(); ++k) {
      renderer.draw_sphere(scene.sphere, scene.surface, viewports[k], kCompareSlots[k]);
    }
  }
}

}  // namespace skinlayer
