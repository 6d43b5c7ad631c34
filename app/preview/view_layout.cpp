#include "app/preview/view_layout.h"

#include <algorithm>
#include <cmath>

namespace skinlayer {

PreviewLayout layout_preview(float window_width, float window_height, float panel_width, ViewKind view) {
  PreviewLayout layout;
  const float panel = std::clamp(panel_width, 0.0f, 0.5f * window_width);
  layout.panel = {0.0f, 0.0f, panel, window_height};
  const Rect area{panel, 0.0f, window_width - panel, window_height};
  if (view == ViewKind::Sphere) layout.sphere = area;
  if (view == ViewKind::Polar) layout.plots = area;
  if (view == ViewKind::Compare) {
    const float third = std::floor(area.width / 3.0f);
    for (int k = 0; k < 3; ++k) {
      const float width = k < 2 ? third : area.width - 2.0f * third;
      layout.compare[k] = {area.x + static_cast<float>(k) * third, area.y, width, area.height};
    }
  }
  if (view == ViewKind::Both) {
    const float half = std::floor(0.5f * area.width);
    layout.sphere = {area.x, area.y, half, area.height};
    layout.plots = {area.x + half, area.y, area.width - half, area.height};
  }
  return layout;
}

Viewport to_viewport(const Rect& rect, std::array<float, 2> scale, int framebuffer_height) {
  const int x0 = static_cast<int>(std::lround(rect.x * scale[0]));
  const int x1 = static_cast<int>(std::lround((rect.x + rect.width) * scale[0]));
  const int y0 = static_cast<int>(std::lround(rect.y * scale[1]));
  const int y1 = static_cast<int>(std::lround((rect.y + rect.height) * scale[1]));
  return Viewport{x0, framebuffer_height - y1, x1 - x0, y1 - y0};
}

float pixels_per_unit(const Rect& rect, double margin) {
  const float shorter = std::max(1.0f, std::min(rect.width, rect.height));
  return static_cast<float>(0.5 * shorter / margin);
}

std::array<double, 2> view_point(const Rect& rect, double margin, float px, float py) {
  const std::array<float, 2> c = rect.center();
  const double unit = pixels_per_unit(rect, margin);
  return {(px - c[0]) / unit, -(py - c[1]) / unit};
}

std::array<float, 2> window_point(const Rect& rect, double margin, double vx, double vy) {
  const std::array<float, 2> c = rect.center();
  const double unit = pixels_per_unit(rect, margin);
  return {static_cast<float>(c[0] + vx * unit), static_cast<float>(c[1] - vy * unit)};
}

LightAngles light_from_sphere_point(const Rect& sphere, float px, float py, double max_theta) {
  std::array<double, 2> p = view_point(sphere, Renderer::kSphereMargin, px, py);
  const double r = std::hypot(p[0], p[1]);
  const double theta = std::min(std::asin(std::min(r, 1.0)), max_theta);
  const double phi = r > 0.0 ? std::atan2(p[1], p[0]) : 0.0;
  return {theta, phi};
}

std::array<float, 2> sphere_point_of_light(const Rect& sphere, const LightAngles& light) {
  const double r = std::sin(light.theta);
  return window_point(sphere, Renderer::kSphereMargin, r * std::cos(light.phi), r * std::sin(light.phi));
}

}  // namespace skinlayer
