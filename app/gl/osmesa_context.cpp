#include "app/gl/osmesa_context.h"

#include <GL/osmesa.h>

#include <stdexcept>
#include <string>

namespace skinlayer::gl {

struct OsmesaContext::Impl {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> buffer;
  ~Impl() {
    if (context != nullptr) OSMesaDestroyContext(context);
  }
};

OsmesaContext::OsmesaContext(int width, int height) : impl_(std::make_unique<Impl>()), width_(width), height_(height) {
  // Mesa 22 gives 4.5 core for a 4.5 request and NULL for 4.6; 3.3 is the fallback.
  for (const int major_minor : {45, 33}) {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              8,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              major_minor / 10,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              major_minor % 10,
                              0};
    impl_->context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (impl_->context != nullptr) break;
  }
  if (impl_->context == nullptr) throw std::runtime_error("OSMesa could not create an OpenGL core-profile context");
  impl_->buffer.resize(static_cast<std::size_t>(width) * height * 4);
  make_current();
}

OsmesaContext::~OsmesaContext() = default;

void OsmesaContext::make_current() {
  if (!OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), 0x1401 /* GL_UNSIGNED_BYTE */, width_, height_)) {
    throw std::runtime_error("OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" +
                             std::to_string(height_) + " buffer");
  }
}

}  // namespace skinlayer::gl
