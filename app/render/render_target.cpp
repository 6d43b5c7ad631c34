#include "app/render/render_target.h"

#include <stdexcept>
#include <string>

namespace skinlayer {
namespace {

template <class T>
std::vector<T> flip_rows(std::vector<T> pixels, int width, int height) {
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height / 2; ++y) {
    std::swap_ranges(pixels.begin() + static_cast<std::ptrdiff_t>(y * row),
                     pixels.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                     pixels.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row));
  }
  return pixels;
}

}  // namespace

RenderTarget::RenderTarget(int width, int height, PixelFormat format)
    : width_(width),
      height_(height),
      format_(format),
      framebuffer_(gl::create_framebuffer()),
      color_(gl::create_texture()),
      depth_(gl::create_renderbuffer()) {
  if (width < 1 || height < 1) throw std::invalid_argument("RenderTarget: size must be positive");
  glBindTexture(GL_TEXTURE_2D, color_.get());
  if (format == PixelFormat::Rgba8) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  } else {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.get(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("RenderTarget: framebuffer incomplete (status " + std::to_string(status) + ")");
  }
  gl::check_errors("RenderTarget()");
}

void RenderTarget::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get()); }
void RenderTarget::unbind() { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

std::vector<std::uint8_t> RenderTarget::read_rgba8() const {
  bind();
  std::vector<std::uint8_t> pixels = read_bound_rgba8(0, 0, width_, height_);
  unbind();
  return pixels;
}

std::vector<float> RenderTarget::read_rgba32f() const {
  if (format_ != PixelFormat::Rgba32F) throw std::logic_error("RenderTarget: not a float target");
  bind();
  std::vector<float> pixels(static_cast<std::size_t>(width_) * height_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, pixels.data());
  unbind();
  gl::check_errors("RenderTarget::read_rgba32f");
  return flip_rows(std::move(pixels), width_, height_);
}

std::vector<std::uint8_t> read_bound_rgba8(int x, int y, int width, int height) {
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  gl::check_errors("read_bound_rgba8");
  return flip_rows(std::move(pixels), width, height);
}

}  // namespace skinlayer
