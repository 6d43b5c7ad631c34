#include "app/figures/xy_plot.h"

#include <algorithm>
#include <cmath>

namespace skinlayer::figures {

Image draw_xy_plot(const XyPlot& plot, const Font& font) {
  const double u = plot.height / 360.0;  // layout unit: one pixel of the 360-pixel-high design
  Canvas canvas(plot.width, plot.height, kPlotBackground);
  canvas.text(font, plot.title, {plot.width / 2.0, 22 * u}, 16 * u, kPlotInk, Align::Center);

  double top_value = 0.0;
  for (const XySeries& s : plot.series) {
    for (const Point& p : s.curve) top_value = std::max(top_value, p.y);
    for (const ErrorBarPoint& p : s.points) top_value = std::max(top_value, p.y + p.error);
    for (const LevelBar& b : s.levels) top_value = std::max(top_value, b.y);
  }
  top_value = top_value > 0.0 && std::isfinite(top_value) ? nice_ceiling(top_value) : 1.0;

  const double left = 64 * u, right = plot.width - 16 * u, top = 36 * u, bottom = plot.height - 74 * u;
  const auto to_pixel = [&](double x, double y) {
    const double fx = std::clamp((x - plot.x_min) / (plot.x_max - plot.x_min), 0.0, 1.0);
    const double fy = std::clamp(y / top_value, 0.0, 1.0);
    return Point{left + fx * (right - left), bottom - fy * (bottom - top)};
  };

  constexpr int kYTicks = 4;
  for (int k = 0; k <= kYTicks; ++k) {
    const double value = top_value * k / kYTicks;
    const Point p = to_pixel(plot.x_min, value);
    canvas.line({left, p.y}, {right, p.y}, kPlotGrid, 1.0 * u);
    canvas.text(font, format_axis_value(value), {left - 6 * u, p.y + 4 * u}, 11 * u, kPlotMuted, Align::Right);
  }
  for (double x = plot.x_min; x <= plot.x_max + 1e-9 * std::abs(plot.x_max); x += plot.x_tick) {
    const Point p = to_pixel(x, 0.0);
    canvas.line({p.x, top}, {p.x, bottom}, kPlotGrid, 1.0 * u);
    canvas.text(font, format_axis_value(x), {p.x, bottom + 15 * u}, 11 * u, kPlotMuted, Align::Center);
  }
  canvas.line({left, bottom}, {right, bottom}, kPlotInk, 1.4 * u);
  canvas.line({left, top}, {left, bottom}, kPlotInk, 1.4 * u);
  canvas.text(font, plot.x_label, {(left + right) / 2.0, bottom + 33 * u}, 12 * u, kPlotInk, Align::Center);
  canvas.text(font, plot.y_label, {left - 56 * u, top - 10 * u}, 12 * u, kPlotInk, Align::Left);

  for (const XySeries& s : plot.series) {
    std::vector<Point> pixels;
    pixels.reserve(s.curve.size());
    for (const Point& p : s.curve) pixels.push_back(to_pixel(p.x, p.y));
    canvas.polyline(pixels, s.color, 1.6 * u);
    for (const LevelBar& b : s.levels) canvas.line(to_pixel(b.x_min, b.y), to_pixel(b.x_max, b.y), s.color, 2.4 * u);
    for (const ErrorBarPoint& p : s.points) {
      const Point low = to_pixel(p.x, p.y - p.error), high = to_pixel(p.x, p.y + p.error);
      canvas.line(low, high, s.color, 1.4 * u);
      canvas.line({low.x - 3 * u, low.y}, {low.x + 3 * u, low.y}, s.color, 1.4 * u);
      canvas.line({high.x - 3 * u, high.y}, {high.x + 3 * u, high.y}, s.color, 1.4 * u);
      canvas.fill_circle(to_pixel(p.x, p.y), 3.2 * u, s.color);
    }
  }

  // Legend: one row under the axis label; each entry shows what its series draws.
  const double legend_y = plot.height - 14 * u, legend_font = 12 * u, gap = 20 * u;
  std::vector<const XySeries*> entries;
  double total = 0.0;
  for (const XySeries& s : plot.series) {
    if (s.label.empty()) continue;
    entries.push_back(&s);
    total += 26 * u + font.render(s.label, legend_font).width + (entries.size() > 1 ? gap : 0.0);
  }
  double x = std::max(8 * u, (plot.width - total) / 2.0);
  for (const XySeries* s : entries) {
    const Point mid{x + 10 * u, legend_y - 4 * u};
    if (!s->curve.empty()) canvas.line({mid.x - 10 * u, mid.y}, {mid.x + 10 * u, mid.y}, s->color, 1.6 * u);
    if (!s->levels.empty()) canvas.line({mid.x - 7 * u, mid.y}, {mid.x + 7 * u, mid.y}, s->color, 2.4 * u);
    if (!s->points.empty()) canvas.fill_circle(mid, 3.2 * u, s->color);
    x += 26 * u;
    x += canvas.text(font, s->label, {x, legend_y}, legend_font, kPlotInk) + gap;
  }
  return canvas.image();
}

}  // namespace skinlayer::figures
