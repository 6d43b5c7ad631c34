// An offscreen framebuffer with one color texture (RGBA8 for pictures, RGBA32F for measuring radiance) and a
// depth buffer, and read-back of its pixels with the rows flipped to top-down order.
#pragma once

#include <cstdint>
#include <vector>

#include "app/gl/gl_objects.h"

namespace skinlayer {

enum class PixelFormat { Rgba8, Rgba32F };

class RenderTarget {
 public:
  RenderTarget(int width, int height, PixelFormat format);

  int width() const { return width_; }
  int height() const { return height_; }
  void bind() const;  // binds it for drawing
  GLuint color_texture() const { return color_.get(); }
  static void unbind();

  std::vector<std::uint8_t> read_rgba8() const;  // width * height * 4, top row first
  std::vector<float> read_rgba32f() const;       // width * height * 4, top row first

 private:
  int width_;
  int height_;
  PixelFormat format_;
  gl::Framebuffer framebuffer_;
  gl::Texture color_;
  gl::Renderbuffer depth_;
};

// Reads the currently bound framebuffer's RGBA8 pixels (e.g. a window's back buffer), top row first.
std::vector<std::uint8_t> read_bound_rgba8(int x, int y, int width, int height);

}  // namespace skinlayer
