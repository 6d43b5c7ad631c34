// A small CPU raster for the figures: an RGBA8 image with anti-aliased lines and polylines, filled circles and
// text. Coordinates are pixels, x to the right and y down, with pixel (i, j) covering [i, i+1) x [j, j+1).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "app/figures/font.h"
#include "app/render/png_export.h"

namespace skinlayer::figures {

struct Rgba {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  std::uint8_t a = 255;
};

struct Point {
  double x = 0.0;
  double y = 0.0;
};

enum class Align { Left, Center, Right };

class Canvas {
 public:
  Canvas(int width, int height, Rgba background);

  int width() const { return image_.width; }
  int height() const { return image_.height; }
  const Image& image() const { return image_; }

  // A segment `line_width` pixels wide with round caps; coverage from the distance to the segment (1 px ramp).
  void line(Point from, Point to, Rgba color, double line_width);
  void polyline(std::span<const Point> points, Rgba color, double line_width);
  // The circle outline, drawn as a 360-segment polyline.
  void circle(Point center, double radius, Rgba color, double line_width);
  void fill_circle(Point center, double radius, Rgba color);
  void fill_rect(Point top_left, Point bottom_right, Rgba color);

  // Text whose baseline starts at `baseline` (aligned left, centered or right on its x). Returns its width [px].
  double text(const Font& font, std::string_view utf8, Point baseline, double pixel_height, Rgba color,
              Align align = Align::Left);

  // Copies an image with its top-left corner at (x, y); parts outside the canvas are clipped.
  void blit(const Image& source, int x, int y);

 private:
  void blend(int x, int y, Rgba color, double coverage);

  Image image_;
};

}  // namespace skinlayer::figures
