// Move-only RAII owners of OpenGL objects. Each deletes its object when destroyed; a context must be current.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/gl/gl_api.h"

namespace skinlayer::gl {

// One GL name and the function that deletes it.
template <void (*Delete)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint name) : name_(name) {}
  Handle(Handle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { reset(); }

  GLuint get() const { return name_; }
  void reset() {
    if (name_ != 0) Delete(name_);
    name_ = 0;
  }

 private:
  GLuint name_ = 0;
};

void delete_program(GLuint name);
void delete_texture(GLuint name);
void delete_framebuffer(GLuint name);
void delete_renderbuffer(GLuint name);
void delete_vertex_array(GLuint name);

using Program = Handle<delete_program>;
using Texture = Handle<delete_texture>;
using Framebuffer = Handle<delete_framebuffer>;
using Renderbuffer = Handle<delete_renderbuffer>;
using VertexArray = Handle<delete_vertex_array>;

Texture create_texture();
Framebuffer create_framebuffer();
Renderbuffer create_renderbuffer();
VertexArray create_vertex_array();

// Compiles and links a program from vertex and fragment sources, each given as a list of pieces that are
// concatenated in order. Throws std::runtime_error with the GL info log on failure.
Program link_program(const std::vector<std::string_view>& vertex, const std::vector<std::string_view>& fragment);

// Throws std::runtime_error naming `where` if glGetError reports an error.
void check_errors(std::string_view where);

}  // namespace skinlayer::gl
