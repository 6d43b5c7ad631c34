#include "app/gl/gl_objects.h"

#include <stdexcept>

namespace skinlayer::gl {

void delete_program(GLuint name) { glDeleteProgram(name); }
void delete_texture(GLuint name) { glDeleteTextures(1, &name); }
void delete_framebuffer(GLuint name) { glDeleteFramebuffers(1, &name); }
void delete_renderbuffer(GLuint name) { glDeleteRenderbuffers(1, &name); }
void delete_vertex_array(GLuint name) { glDeleteVertexArrays(1, &name); }

namespace {

// One new name from a glGen* function, owned by the handle type H.
template <class H, void (*Generate)(GLsizei, GLuint*)>
H generate() {
  GLuint name = 0;
  Generate(1, &name);
  return H(name);
}

}  // namespace

Texture create_texture() { return generate<Texture, glGenTextures>(); }
Framebuffer create_framebuffer() { return generate<Framebuffer, glGenFramebuffers>(); }
Renderbuffer create_renderbuffer() { return generate<Renderbuffer, glGenRenderbuffers>(); }
VertexArray create_vertex_array() { return generate<VertexArray, glGenVertexArrays>(); }

namespace {

GLuint compile(GLenum stage, const std::vector<std::string_view>& pieces) {
  std::vector<const GLchar*> strings;
  std::vector<GLint> lengths;
  for (std::string_view piece : pieces) {
    strings.push_back(piece.data());
    lengths.push_back(static_cast<GLint>(piece.size()));
  }
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, static_cast<GLsizei>(strings.size()), strings.data(), lengths.data());
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error("GLSL compile error: " + log);
  }
  return shader;
}

}  // namespace

Program link_program(const std::vector<std::string_view>& vertex, const std::vector<std::string_view>& fragment) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragment);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  Program program(glCreateProgram());
  glAttachShader(program.get(), vs);
  glAttachShader(program.get(), fs);
  glLinkProgram(program.get());
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(program.get(), GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program.get(), length, nullptr, log.data());
    throw std::runtime_error("GLSL link error: " + log);
  }
  return program;
}

void check_errors(std::string_view where) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    throw std::runtime_error("OpenGL error " + std::to_string(error) + " in " + std::string(where));
  }
}

}  // namespace skinlayer::gl
