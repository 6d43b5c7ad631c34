#include "app/figures/polar_plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <set>

#include "app/figures/plot_style.h"
#include "core/conventions.h"

namespace skinlayer::figures {

Image draw_polar_plot(const PolarPlot& plot, const Font& font) {
  const double u = plot.size / 640.0;  // layout unit: one pixel of the 640-pixel design
  Canvas canvas(plot.size, plot.size, kPlotBackground);
  canvas.text(font, plot.title, {plot.size / 2.0, 28 * u}, 21 * u, kPlotInk, Align::Center);
  canvas.text(font, plot.subtitle, {plot.size / 2.0, 52 * u}, 15 * u, kPlotMuted, Align::Center);

  // Legend: swatch and label per curve, wrapped into centered rows at the bottom.
  const double legend_font = 15 * u, swatch = 6 * u, gap = 22 * u, row_height = 22 * u;
  std::vector<std::vector<std::size_t>> rows(1);
  std::vector<double> row_widths(1, 0.0);
  std::vector<double> label_widths;
  for (std::size_t k = 0; k < plot.curves.size(); ++k) {
    const double w = 2 * swatch + 6 * u + font.render(plot.curves[k].label, legend_font).width;
    label_widths.push_back(w);
    if (!rows.back().empty() && row_widths.back() + gap + w > plot.size - 40 * u) {
      rows.emplace_back();
      row_widths.push_back(0.0);
    }
    row_widths.back() += (rows.back().empty() ? 0.0 : gap) + w;
    rows.back().push_back(k);
  }
  const double legend_top = plot.size - 14 * u - row_height * static_cast<double>(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    double x = (plot.size - row_widths[r]) / 2.0;
    const double y = legend_top + row_height * (static_cast<double>(r) + 0.75);
    for (std::size_t k : rows[r]) {
      canvas.fill_circle({x + swatch, y - 5 * u}, swatch, plot.curves[k].color);
      canvas.text(font, plot.curves[k].label, {x + 2 * swatch + 6 * u, y}, legend_font, kPlotInk);
      x += label_widths[k] + gap;
    }
  }

  // The plot: a full circle (reflection above, transmission below) between the title and the legend.
  const double top = 66 * u, bottom = legend_top - 6 * u;
  const Point center{plot.size / 2.0, (top + bottom) / 2.0};
  const double radius = std::min((bottom - top) / 2.0 - 24 * u, plot.size / 2.0 - 70 * u);
  std::array<double, 2> peak = {0.0, 0.0};  // reflection, transmission
  for (const PolarCurve& curve : plot.curves) {
    for (const LobeSample& s : curve.reflection) peak[0] = std::max(peak[0], s.value);
    for (const LobeSample& s : curve.transmission) peak[1] = std::max(peak[1], s.value);
  }
  if (!plot.separate_scales) peak = {std::max(peak[0], peak[1]), std::max(peak[0], peak[1])};
  const bool log_scale = plot.log_decades > 0;
  std::array<double, 2> outer{};
  for (std::size_t h = 0; h < 2; ++h) {
    outer[h] = peak[h] <= 0.0 ? 1.0 : log_scale ? std::pow(10.0, std::ceil(std::log10(peak[h]))) : nice_ceiling(peak[h]);
  }
  const int rings = log_scale ? plot.log_decades : 4;
  const auto radius_of = [&](double value, bool transmission) {  // the plotted radius of a value [px]
    const double top_value = outer[transmission ? 1 : 0];
    if (!log_scale) return radius * value / top_value;
    if (value <= 0.0) return 0.0;
    return radius * std::max(0.0, 1.0 + std::log10(value / top_value) / plot.log_decades);
  };
  const auto ring_value = [&](int k, bool transmission) {  // the value on ring k of rings (k = rings: outer circle)
    const double top_value = outer[transmission ? 1 : 0];
    return log_scale ? top_value * std::pow(10.0, k - rings) : top_value * k / rings;
  };
  const auto at = [&](double signed_theta_deg, double r, bool transmission) {
    const double a = degrees_to_radians(signed_theta_deg);
    return Point{center.x + r * std::sin(a), center.y + (transmission ? 1.0 : -1.0) * r * std::cos(a)};
  };

  for (int k = 1; k <= rings; ++k) canvas.circle(center, radius * k / rings, kPlotGrid, 1.0 * u);
  for (int degrees = -75; degrees <= 75; degrees += 15) {
    for (bool transmission : {false, true}) {
      canvas.line(center, at(degrees, radius, transmission), kPlotGrid, 1.0 * u);
    }
  }
  for (int degrees = -90; degrees <= 90; degrees += 30) {
    const std::string label = std::to_string(std::abs(degrees)) + "°";
    for (bool transmission : {false, true}) {
      if (std::abs(degrees) == 90 && transmission) continue;
      const Point p = at(degrees, radius + 16 * u, transmission);
      canvas.text(font, label, {p.x, p.y + 5 * u}, 13 * u, kPlotMuted, Align::Center);
    }
  }
  // Circle values along the back half of the surface line, and the axis words.
  for (int k = 1; k <= rings; ++k) {
    canvas.text(font, format_axis_value(ring_value(k, false)), {center.x - radius * k / rings + 3 * u, center.y - 4 * u},
                11 * u, kPlotMuted, Align::Left);
    if (plot.separate_scales) {
      canvas.text(font, format_axis_value(ring_value(k, true)), {center.x - radius * k / rings + 3 * u, center.y + 13 * u},
                  11 * u, kPlotMuted, Align::Left);
    }
  }
  canvas.text(font, plot.unit + (log_scale ? " (log scale)" : "") + (plot.separate_scales ? ", R and T scaled apart" : ""), {center.x - radius - 10 * u,
              center.y - radius + 4 * u}, 13 * u, kPlotMuted);
  canvas.text(font, "reflection", {center.x + radius + 10 * u, center.y - radius + 4 * u}, 14 * u, kPlotMuted,
              Align::Right);
  canvas.text(font, "transmission", {center.x + radius + 10 * u, center.y + radius - 14 * u}, 14 * u, kPlotMuted,
              Align::Right);
  canvas.text(font, "back (φ = 0°)", {center.x - radius - 10 * u, center.y + radius + 4 * u}, 13 * u, kPlotMuted);
  canvas.text(font, "forward (φ = 180°)", {center.x + radius + 10 * u, center.y + radius + 4 * u}, 13 * u, kPlotMuted,
              Align::Right);
  canvas.line({center.x - radius - 6 * u, center.y}, {center.x + radius + 6 * u, center.y}, kPlotInk, 1.6 * u);

  // Incident directions (upper left): one dark ray, or one per curve in its color when they differ.
  std::set<double> incidences;
  for (const PolarCurve& curve : plot.curves) incidences.insert(curve.theta_i_deg);
  for (const PolarCurve& curve : plot.curves) {
    const Rgba color = incidences.size() > 1 ? curve.color : kPlotInk;
    const Point far = at(-curve.theta_i_deg, radius * 1.02, false);
    canvas.line(far, at(-curve.theta_i_deg, radius * 0.8, false), color, 2.5 * u);
    canvas.fill_circle(far, 4 * u, color);
    if (incidences.size() == 1) break;
  }
  if (incidences.size() == 1) {
    const Point label = at(-*incidences.begin(), radius * 0.72, false);
    canvas.text(font, "θi = " + format_axis_value(*incidences.begin()) + "°", {label.x, label.y}, 13 * u, kPlotInk,
                Align::Center);
  }

  for (const PolarCurve& curve : plot.curves) {
    for (bool transmission : {false, true}) {
      const std::vector<LobeSample>& lobe = transmission ? curve.transmission : curve.reflection;
      std::vector<Point> points;
      points.reserve(lobe.size());
      for (const LobeSample& s : lobe) points.push_back(at(s.signed_theta_deg, radius_of(s.value, transmission), transmission));
      canvas.polyline(points, curve.color, 2.2 * u);
    }
  }
  return canvas.image();
}

}  // namespace skinlayer::figures
