// An offscreen OpenGL 3.3+ core context through OSMesa (llvmpipe), with its own RGBA8 color buffer. RAII: the
// context is destroyed with the object. Headless rendering and the GL tests use it; the window uses GLFW instead.
#pragma once

#include <memory>
#include <vector>

namespace skinlayer::gl {

class OsmesaContext {
 public:
  // Throws std::runtime_error if no core-profile context can be created.
  OsmesaContext(int width, int height);
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  void make_current();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int width_;
  int height_;
};

}  // namespace skinlayer::gl
