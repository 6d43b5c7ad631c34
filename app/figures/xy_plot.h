// A Cartesian plot for comparing a computed curve with measured points: a frame with ticks and labels, curves,
// points with +- error bars, and short horizontal level bars (a value that holds over an x interval, such as an
// average over a bin), with a legend. y starts at 0 and ends at a round value above everything drawn.
#pragma once

#include <string>
#include <vector>

#include "app/figures/canvas.h"
#include "app/figures/font.h"
#include "app/figures/plot_style.h"
#include "app/render/png_export.h"

namespace skinlayer::figures {

struct ErrorBarPoint {
  double x = 0.0;
  double y = 0.0;
  double error = 0.0;  // half-length of the bar, in y units
};

struct LevelBar {
  double x_min = 0.0;
  double x_max = 0.0;
  double y = 0.0;
};

struct XySeries {
  std::string label;  // legend text; empty: not in the legend
  Rgba color;
  std::vector<Point> curve;            // a polyline through (x, y) in data units
  std::vector<ErrorBarPoint> points;   // filled markers with error bars
  std::vector<LevelBar> levels;        // horizontal bars
};

struct XyPlot {
  std::string title;
  std::string x_label;
  std::string y_label;
  double x_min = 0.0;
  double x_max = 1.0;
  double x_tick = 0.25;  // spacing of the labelled x ticks, from x_min
  std::vector<XySeries> series;
  int width = 720;
  int height = 360;
};

// Draws the plot. Values outside [x_min, x_max] or above the top of the y axis are clipped to the frame's edge.
Image draw_xy_plot(const XyPlot& plot, const Font& font);

}  // namespace skinlayer::figures
