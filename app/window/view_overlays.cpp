#include "app/window/view_overlays.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "app/preview/lobe_probe.h"
#include "app/window/profile_plot.h"
#include "core/conventions.h"

namespace skinlayer {
namespace {

constexpr ImU32 kLabelColor = IM_COL32(220, 220, 220, 255);
constexpr ImU32 kDimColor = IM_COL32(170, 170, 170, 255);
// The fill colors of shaders/lobe.frag, for the legend.
constexpr ImU32 kSubsurfaceReflection = IM_COL32(217, 115, 89, 255);
constexpr ImU32 kSubsurfaceTransmission = IM_COL32(89, 140, 217, 255);
constexpr ImU32 kSurface = IM_COL32(242, 217, 102, 255);

ImVec2 to_imvec(std::array<float, 2> p) { return {p[0], p[1]}; }

// Text centred on a point, kept inside rect.
void centred_text(ImDrawList& draw, const Rect& rect, ImVec2 at, const std::string& text, ImU32 color) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const float x = std::clamp(at.x - 0.5f * size.x, rect.x + 2.0f, rect.x + rect.width - size.x - 2.0f);
  const float y = std::clamp(at.y - 0.5f * size.y, rect.y + 2.0f, rect.y + rect.height - size.y - 2.0f);
  draw.AddText(ImVec2(x, y), color, text.c_str());
}

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

void angle_labels(ImDrawList& draw, const Rect& plots) {
  const double margin = Renderer::kLobeMargin;
  const float unit = pixels_per_unit(plots, margin);
  const double out = 1.0 + 14.0 / std::max(unit, 1.0f);  // 14 pixels outside the outer circle
  const char* degree = "%.0f°";
  for (int degrees = 0; degrees <= 90; degrees += 30) {
    const double t = degrees_to_radians(degrees);
    for (int side : {-1, 1}) {                      // back (left), forward (right)
      for (int half : {1, -1}) {                    // reflection (up), transmission (down)
        if (degrees == 0 && side == -1) continue;   // the normal: one label per half
        if (degrees == 90 && half == -1) continue;  // the surface line: one label per side
        const double x = side * std::sin(t) * out;
        const double y = half * std::cos(t) * out;
        ImVec2 at = to_imvec(window_point(plots, margin, x, y));
        if (degrees == 90) at.y -= ImGui::GetFontSize() * 0.8f;  // above the surface line
        centred_text(draw, plots, at, format(degree, degrees), kDimColor);
      }
    }
  }
}

void ring_labels(ImDrawList& draw, const Rect& plots, const LobeView& lobes) {
  const double margin = Renderer::kLobeMargin;
  for (int k = 1; k <= 4; ++k) {
    const double r = 0.25 * k;
    const double value = lobe_value_at_radius(lobes, r);
    const ImVec2 at = to_imvec(window_point(plots, margin, 0.0, r));
    const std::string text = format(lobes.log_scale ? "%.2g" : "%.3g", value);
    draw.AddText(ImVec2(at.x + 3.0f, at.y + 1.0f), kDimColor, text.c_str());  // just inside the ring
  }
}

void captions(ImDrawList& draw, const Rect& plots, const LobeView& lobes, bool unicode) {
  const float pad = 6.0f;
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const std::string incidence =
      format(unicode ? "reflection (BRDF), θi = %.1f°" : "reflection (BRDF), theta_i = %.1f deg",
             radians_to_degrees(lobes.theta_i));
  draw.AddText(ImVec2(plots.x + pad, plots.y + pad), kLabelColor, incidence.c_str());
  const std::string scale = lobes.log_scale ? format("log radius, %.0f decades; unit 1/sr", lobes.decades)
                                            : std::string("linear radius; unit 1/sr");
  draw.AddText(ImVec2(plots.x + pad, plots.y + pad + line), kDimColor, scale.c_str());
  const float bottom = plots.y + plots.height - pad - line;
  draw.AddText(ImVec2(plots.x + pad, bottom - 3.0f * line), kLabelColor, "transmission (BTDF)");
  const std::array<std::pair<ImU32, const char*>, 3> legend = {
      std::pair{kSubsurfaceReflection, "subsurface, reflected"},
      std::pair{kSubsurfaceTransmission, "subsurface, transmitted"}, std::pair{kSurface, "surface (top interface)"}};
  for (std::size_t k = 0; k < legend.size(); ++k) {
    const float y = bottom - static_cast<float>(2 - k) * line;
    const float box = ImGui::GetFontSize() * 0.8f;
    draw.AddRectFilled(ImVec2(plots.x + pad, y + 0.1f * box), ImVec2(plots.x + pad + box, y + 1.1f * box),
                       legend[k].first);
    draw.AddText(ImVec2(plots.x + pad + box + 5.0f, y), kDimColor, legend[k].second);
  }
}

// The value under the mouse: a ray from the centre to the lobe along the mouse direction, and a tooltip.
void probe_under_mouse(ImDrawList& draw, const Rect& plots, const ColorTables& tables, const LobeView& lobes,
                       bool unicode) {
  const double margin = Renderer::kLobeMargin;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const std::array<double, 2> p = view_point(plots, margin, mouse.x, mouse.y);
  const double length = std::hypot(p[0], p[1]);
  if (length < 1e-9) return;
  const LobeSample sample = probe_lobe(tables, lobes.theta_i, p[0], p[1]);
  const double r = lobe_radius(lobes, sample.plotted_total());
  const ImVec2 centre = to_imvec(window_point(plots, margin, 0.0, 0.0));
  const ImVec2 tip = to_imvec(window_point(plots, margin, p[0] / length * r, p[1] / length * r));
  draw.AddLine(centre, tip, IM_COL32(255, 255, 255, 200), 1.5f);
  draw.AddCircleFilled(tip, 3.5f, IM_COL32(255, 255, 255, 230));

  const double degrees = radians_to_degrees(sample.theta_o);
  const char* side = sample.phi > 0.0 ? "forward" : "back";
  ImGui::BeginTooltip();
  if (sample.reflection) {
    ImGui::Text(unicode ? "reflection, θo = %.1f° (%s side)" : "reflection, theta_o = %.1f deg (%s side)", degrees,
                side);
    ImGui::Text("BRDF = %.4g 1/sr (mean of R, G, B)", sample.plotted_total());
    ImGui::Text("  surface %.4g + subsurface %.4g", sample.surface, sample.plotted_subsurface());
  } else {
    ImGui::Text(unicode ? "transmission, θo = %.1f° (%s side)" : "transmission, theta_o = %.1f deg (%s side)", degrees,
                side);
    ImGui::Text("BTDF = %.4g 1/sr (mean of R, G, B)", sample.plotted_total());
  }
  ImGui::Text("  R %.4g   G %.4g   B %.4g", sample.total[0], sample.total[1], sample.total[2]);
  ImGui::EndTooltip();
}

// A drag that starts within this many pixels of the A/B split line moves the line, not the light.
constexpr float kSplitGrab = 8.0f;

// The A/B split line's x on screen (Renderer::draw_split_sphere draws it there).
float split_line_x(const Rect& sphere, double split) { return sphere.x + static_cast<float>(split) * sphere.width; }

bool sphere_drag(const Rect& sphere, LightState& light, ComparisonState& comparison) {
  ImGui::SetCursorScreenPos(ImVec2(sphere.x, sphere.y));
  ImGui::InvisibleButton("sphere", ImVec2(sphere.width, sphere.height));
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const float line = split_line_x(sphere, comparison.split);
  const bool near_line = comparison.pinned && std::abs(mouse.x - line) <= kSplitGrab;
  if (near_line && ImGui::IsItemHovered()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
  // Which drag this is, kept while the button is held (ImGui's storage, as the sliders' reset press).
  const ImGuiID split_drag = ImGui::GetID("split-drag");
  ImGuiStorage* storage = ImGui::GetStateStorage();
  if (ImGui::IsItemActivated()) storage->SetBool(split_drag, near_line);
  if (!ImGui::IsItemActive()) return false;
  if (storage->GetBool(split_drag, false) && comparison.pinned) {
    const double before = comparison.split;
    comparison.split = std::clamp(static_cast<double>((mouse.x - sphere.x) / sphere.width), 0.0, 1.0);
    ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    return comparison.split != before;
  }
  const LightAngles angles =
      light_from_sphere_point(sphere, mouse.x, mouse.y, degrees_to_radians(kMaxLightThetaDegrees));
  const LightState before = light;
  light.theta_degrees = radians_to_degrees(angles.theta);
  if (angles.theta > 0.0) light.phi_degrees = radians_to_degrees(angles.phi);
  return light.theta_degrees != before.theta_degrees || light.phi_degrees != before.phi_degrees;
}

void light_marker(ImDrawList& draw, const Rect& sphere, const LightState& light) {
  const LightAngles angles{degrees_to_radians(light.theta_degrees), degrees_to_radians(light.phi_degrees)};
  const ImVec2 at = to_imvec(sphere_point_of_light(sphere, angles));
  draw.AddCircle(at, 6.0f, IM_COL32(255, 230, 120, 220), 0, 2.0f);
  draw.AddText(ImVec2(sphere.x + 6.0f, sphere.y + 6.0f), kDimColor, "drag on the sphere to move the light");
}

}  // namespace

bool view_overlays(const ViewOverlayInput& input, LightState& light, ComparisonState& comparison) {
  const PreviewLayout& layout = input.layout;
  const float left = layout.panel.x + layout.panel.width;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(left, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(std::max(io.DisplaySize.x - left, 1.0f), std::max(io.DisplaySize.y, 1.0f)));
  constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoFocusOnAppearing |
                                     ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoScrollWithMouse;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
  ImGui::Begin("##views", nullptr, flags);
  ImGui::PopStyleVar();
  ImDrawList& draw = *ImGui::GetWindowDrawList();
  bool changed = false;
  if (!layout.sphere.empty()) {
    changed = sphere_drag(layout.sphere, light, comparison);
    light_marker(draw, layout.sphere, light);
    if (comparison.pinned) {  // which side is which
      const Rect& sphere = layout.sphere;
      const float line = split_line_x(sphere, comparison.split);
      const float y = sphere.y + sphere.height - ImGui::GetTextLineHeight() - 10.0f;
      draw.AddText(ImVec2(line - ImGui::CalcTextSize("A (edited)").x - 8.0f, y), kLabelColor, "A (edited)");
      draw.AddText(ImVec2(line + 8.0f, y), kLabelColor, comparison.label.c_str());
    }
  }
  if (!layout.compare[0].empty()) {  // Stam's last results slide: the same light on three models
    constexpr std::array<const char*, 3> kNames = {"Lambert", "Hanrahan-Krueger", "new model (Stam 2001)"};
    for (std::size_t k = 0; k < kNames.size(); ++k) {
      const Rect& rect = layout.compare[k];
      const ImVec2 size = ImGui::CalcTextSize(kNames[k]);
      draw.AddText(ImVec2(rect.x + 0.5f * (rect.width - size.x), rect.y + rect.height - size.y - 12.0f), kLabelColor,
                   kNames[k]);
    }
  }
  if (!layout.plots.empty()) {
    ImGui::SetCursorScreenPos(ImVec2(layout.plots.x, layout.plots.y));
    ImGui::InvisibleButton("plots", ImVec2(layout.plots.width, layout.plots.height));
    const bool hovered = ImGui::IsItemHovered();
    if (input.tables != nullptr) {
      angle_labels(draw, layout.plots);
      ring_labels(draw, layout.plots, input.lobes);
      captions(draw, layout.plots, input.lobes, input.unicode);
      if (hovered) probe_under_mouse(draw, layout.plots, *input.tables, input.lobes, input.unicode);
      if (input.profile != nullptr) draw_profile_plot(draw, layout.plots, *input.profile);
    }
  }
  if (input.tables == nullptr) {
    const char* text = "solving…";
    const ImVec2 size = ImGui::CalcTextSize(text);
    draw.AddText(ImVec2(left + 0.5f * (io.DisplaySize.x - left - size.x), 0.5f * (io.DisplaySize.y - size.y)),
                 kLabelColor, input.unicode ? text : "solving...");
  }
  ImGui::End();
  return changed;
}

}  // namespace skinlayer
