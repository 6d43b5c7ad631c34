#include "app/window/profile_plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace skinlayer {
namespace {

constexpr double kDecades = 4.0;
constexpr std::array<ImU32, 3> kChannelColors = {IM_COL32(235, 90, 80, 255), IM_COL32(110, 205, 110, 255),
                                                 IM_COL32(100, 150, 240, 255)};

}  // namespace

void draw_profile_plot(ImDrawList& draw, const Rect& plots, const SpreadProfile& profile) {
  if (profile.per_area.empty() || profile.edges_mm.size() < 2) return;
  double peak = 0.0;
  for (const std::vector<double>& channel : profile.per_area) {
    for (const double v : channel) peak = std::max(peak, v);
  }
  if (!(peak > 0.0)) return;
  const double floor = peak * std::pow(10.0, -kDecades);
  // Out to where every channel has fallen below the floor.
  double reach = 0.5;
  for (const std::vector<double>& channel : profile.per_area) {
    for (std::size_t i = 0; i < channel.size(); ++i) {
      if (channel[i] > floor) reach = std::max(reach, profile.edges_mm[i + 1]);
    }
  }
  reach = std::min(reach, 20.0);

  const float line = ImGui::GetTextLineHeight();
  const float width = 0.38f * plots.width, height = 0.24f * plots.height;
  const ImVec2 low(plots.x + plots.width - width - 10.0f, plots.y + plots.height - 10.0f - line);
  const ImVec2 high(low.x + width, low.y - height);
  draw.AddRectFilled(ImVec2(low.x, high.y), ImVec2(high.x, low.y), IM_COL32(20, 20, 24, 220));
  draw.AddRect(ImVec2(low.x, high.y), ImVec2(high.x, low.y), IM_COL32(120, 120, 120, 255));
  const auto at = [&](double r, double value) {
    const double x = std::clamp(r / reach, 0.0, 1.0);
    const double y = std::clamp((std::log10(std::max(value, floor)) - std::log10(floor)) / kDecades, 0.0, 1.0);
    return ImVec2(low.x + static_cast<float>(x) * width, low.y - static_cast<float>(y) * height);
  };
  for (std::size_t c = 0; c < profile.per_area.size() && c < kChannelColors.size(); ++c) {
    std::vector<ImVec2> points;
    for (std::size_t i = 0; i < profile.per_area[c].size(); ++i) {
      const double mid = 0.5 * (profile.edges_mm[i] + profile.edges_mm[i + 1]);
      if (mid > reach) break;
      points.push_back(at(mid, profile.per_area[c][i]));
    }
    draw.AddPolyline(points.data(), static_cast<int>(points.size()), kChannelColors[c], ImDrawFlags_None, 1.5f);
  }
  char caption[96];
  std::snprintf(caption, sizeof caption, "log R(r), 1/mm^2, %.0f dec.", kDecades);
  draw.AddText(ImVec2(low.x + 4.0f, high.y + 2.0f), IM_COL32(200, 200, 200, 255), caption);
  char axis[32];
  std::snprintf(axis, sizeof axis, "%.3g mm", reach);
  const ImVec2 size = ImGui::CalcTextSize(axis);
  draw.AddText(ImVec2(high.x - size.x, low.y + 1.0f), IM_COL32(170, 170, 170, 255), axis);
  draw.AddText(ImVec2(low.x, low.y + 1.0f), IM_COL32(170, 170, 170, 255), "0");
}

}  // namespace skinlayer
