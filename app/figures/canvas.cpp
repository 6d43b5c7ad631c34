#include "app/figures/canvas.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/conventions.h"

namespace skinlayer::figures {
namespace {

// Distance from p to the segment a-b.
double segment_distance(Point p, Point a, Point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

}  // namespace

Canvas::Canvas(int width, int height, Rgba background) {
  image_.width = width;
  image_.height = height;
  image_.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t k = 0; k < image_.rgba.size(); k += 4) {
    image_.rgba[k] = background.r;
    image_.rgba[k + 1] = background.g;
    image_.rgba[k + 2] = background.b;
    image_.rgba[k + 3] = background.a;
  }
}

void Canvas::blend(int x, int y, Rgba color, double coverage) {
  if (x < 0 || y < 0 || x >= image_.width || y >= image_.height || coverage <= 0.0) return;
  const double alpha = std::min(coverage, 1.0) * color.a / 255.0;
  std::uint8_t* pixel = &image_.rgba[(static_cast<std::size_t>(y) * image_.width + x) * 4];
  const auto mix = [alpha](std::uint8_t under, std::uint8_t over) {
    return static_cast<std::uint8_t>(std::lround(under + (over - under) * alpha));
  };
  pixel[0] = mix(pixel[0], color.r);
  pixel[1] = mix(pixel[1], color.g);
  pixel[2] = mix(pixel[2], color.b);
  pixel[3] = static_cast<std::uint8_t>(std::lround(pixel[3] + (255 - pixel[3]) * alpha));
}

void Canvas::line(Point from, Point to, Rgba color, double line_width) {
  const double reach = line_width / 2.0 + 1.0;
  const int x0 = static_cast<int>(std::floor(std::min(from.x, to.x) - reach));
  const int x1 = static_cast<int>(std::ceil(std::max(from.x, to.x) + reach));
  const int y0 = static_cast<int>(std::floor(std::min(from.y, to.y) - reach));
  const int y1 = static_cast<int>(std::ceil(std::max(from.y, to.y) + reach));
  for (int y = std::max(y0, 0); y <= std::min(y1, image_.height - 1); ++y) {
    for (int x = std::max(x0, 0); x <= std::min(x1, image_.width - 1); ++x) {
      const double d = segment_distance({x + 0.5, y + 0.5}, from, to);
      blend(x, y, color, std::clamp(line_width / 2.0 + 0.5 - d, 0.0, 1.0));
    }
  }
}

void Canvas::polyline(std::span<const Point> points, Rgba color, double line_width) {
  // Each pixel takes the largest coverage over the segments near it, so joints are not blended twice.
  if (points.empty()) return;
  const double reach = line_width / 2.0 + 1.0;
  double xmin = points[0].x, xmax = xmin, ymin = points[0].y, ymax = ymin;
  for (const Point& p : points) {
    xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  }
  const int x0 = std::max(static_cast<int>(std::floor(xmin - reach)), 0);
  const int y0 = std::max(static_cast<int>(std::floor(ymin - reach)), 0);
  const int x1 = std::min(static_cast<int>(std::ceil(xmax + reach)), image_.width - 1);
  const int y1 = std::min(static_cast<int>(std::ceil(ymax + reach)), image_.height - 1);
  if (x1 < x0 || y1 < y0) return;
  const int w = x1 - x0 + 1;
  std::vector<double> coverage(static_cast<std::size_t>(w) * (y1 - y0 + 1), 0.0);
  const std::size_t segments = points.size() == 1 ? 1 : points.size() - 1;
  for (std::size_t k = 0; k < segments; ++k) {
    const Point a = points[k], b = points[std::min(k + 1, points.size() - 1)];
    const int sx0 = std::max(static_cast<int>(std::floor(std::min(a.x, b.x) - reach)), x0);
    const int sx1 = std::min(static_cast<int>(std::ceil(std::max(a.x, b.x) + reach)), x1);
    const int sy0 = std::max(static_cast<int>(std::floor(std::min(a.y, b.y) - reach)), y0);
    const int sy1 = std::min(static_cast<int>(std::ceil(std::max(a.y, b.y) + reach)), y1);
    for (int y = sy0; y <= sy1; ++y) {
      for (int x = sx0; x <= sx1; ++x) {
        const double c = std::clamp(line_width / 2.0 + 0.5 - segment_distance({x + 0.5, y + 0.5}, a, b), 0.0, 1.0);
        double& cell = coverage[static_cast<std::size_t>(y - y0) * w + (x - x0)];
        cell = std::max(cell, c);
      }
    }
  }
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) blend(x, y, color, coverage[static_cast<std::size_t>(y - y0) * w + (x - x0)]);
  }
}

void Canvas::circle(Point center, double radius, Rgba color, double line_width) {
  std::vector<Point> points(361);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double angle = degrees_to_radians(static_cast<double>(k));
    points[k] = {center.x + radius * std::cos(angle), center.y + radius * std::sin(angle)};
  }
  polyline(points, color, line_width);
}

void Canvas::fill_circle(Point center, double radius, Rgba color) {
  const int x0 = static_cast<int>(std::floor(center.x - radius - 1.0));
  const int x1 = static_cast<int>(std::ceil(center.x + radius + 1.0));
  const int y0 = static_cast<int>(std::floor(center.y - radius - 1.0));
  const int y1 = static_cast<int>(std::ceil(center.y + radius + 1.0));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double d = std::hypot(x + 0.5 - center.x, y + 0.5 - center.y);
      blend(x, y, color, std::clamp(radius + 0.5 - d, 0.0, 1.0));
    }
  }
}

void Canvas::fill_rect(Point top_left, Point bottom_right, Rgba color) {
  for (int y = static_cast<int>(std::floor(top_left.y)); y < static_cast<int>(std::ceil(bottom_right.y)); ++y) {
    for (int x = static_cast<int>(std::floor(top_left.x)); x < static_cast<int>(std::ceil(bottom_right.x)); ++x) {
      blend(x, y, color, 1.0);
    }
  }
}

double Canvas::text(const Font& font, std::string_view utf8, Point baseline, double pixel_height, Rgba color,
                    Align align) {
  const TextMask mask = font.render(utf8, pixel_height);
  double left = baseline.x;
  if (align == Align::Center) left -= mask.width / 2.0;
  if (align == Align::Right) left -= mask.width;
  const int x0 = static_cast<int>(std::lround(left));
  const int y0 = static_cast<int>(std::lround(baseline.y)) - mask.baseline;
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      blend(x0 + x, y0 + y, color, mask.coverage[static_cast<std::size_t>(y) * mask.width + x] / 255.0);
    }
  }
  return mask.width;
}

void Canvas::blit(const Image& source, int x, int y) {
  for (int row = 0; row < source.height; ++row) {
    for (int col = 0; col < source.width; ++col) {
      const int tx = x + col, ty = y + row;
      if (tx < 0 || ty < 0 || tx >= image_.width || ty >= image_.height) continue;
      std::copy_n(&source.rgba[(static_cast<std::size_t>(row) * source.width + col) * 4], 4,
                  &image_.rgba[(static_cast<std::size_t>(ty) * image_.width + tx) * 4]);
    }
  }
}

}  // namespace skinlayer::figures
