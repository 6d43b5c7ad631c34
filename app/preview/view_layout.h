// Where the previewer's parts lie in the window, and the maps between window points and the views' own
// coordinates. Pure geometry (no GL, no ImGui), so it is shared by drawing, picking and tests.
//
// Window coordinates are ImGui's: logical pixels, origin at the top-left, y down. Framebuffer viewports are GL's:
// framebuffer pixels, origin at the bottom-left. The views map their rectangle exactly as the shaders do
// (Renderer::view_extent): the shorter side spans 2 * margin units, centred.
#pragma once

#include <array>

#include "app/render/renderer.h"
#include "app/render/scene.h"

namespace skinlayer {

struct Rect {
  float x = 0.0f;
  float y = 0.0f;
  float width = 0.0f;
  float height = 0.0f;

  bool empty() const { return width <= 0.0f || height <= 0.0f; }
  bool contains(float px, float py) const { return px >= x && px < x + width && py >= y && py < y + height; }
  std::array<float, 2> center() const { return {x + 0.5f * width, y + 0.5f * height}; }
};

// The controls panel's width in ImGui units at content scale 1 (the previewer scales it with the content).
inline constexpr float kPanelWidth = 390.0f;

struct PreviewLayout {
  Rect panel;   // the controls, full height on the left
  Rect sphere;  // empty when the view kind hides it
  Rect plots;   // empty when the view kind hides it
  std::array<Rect, 3> compare{};  // Compare only: Lambert | Hanrahan-Krueger | layer model spheres
};

// The panel takes panel_width on the left (at most half the window); the views share the rest as
// scene_viewports() shares a frame (sphere left, plots right for Both).
PreviewLayout layout_preview(float window_width, float window_height, float panel_width, ViewKind view);

// The framebuffer viewport of a window rectangle; scale = framebuffer pixels per window pixel, per axis.
Viewport to_viewport(const Rect& rect, std::array<float, 2> scale, int framebuffer_height);

// Window pixels per unit of the view's coordinates (sphere radius or plot radius).
float pixels_per_unit(const Rect& rect, double margin);

// A window point in the view's coordinates (x right, y up, units of Renderer::kSphereMargin / kLobeMargin's unit),
// and back.
std::array<double, 2> view_point(const Rect& rect, double margin, float px, float py);
std::array<float, 2> window_point(const Rect& rect, double margin, double vx, double vy);

// Light angles in radians, as light_direction() takes them.
struct LightAngles {
  double theta = 0.0;
  double phi = 0.0;
};

// Dragging on the sphere: the light that points along the sphere's normal under the window point (so that point
// is lit head-on). Points off the sphere are taken on its rim, with theta limited to max_theta.
LightAngles light_from_sphere_point(const Rect& sphere, float px, float py, double max_theta);

// Where light_from_sphere_point() would put the given light: the window point of the normal along the light.
std::array<float, 2> sphere_point_of_light(const Rect& sphere, const LightAngles& light);

}  // namespace skinlayer
