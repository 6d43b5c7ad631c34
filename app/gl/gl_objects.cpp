#include "app/gl/gl_objects.h"

#include <stdexcept>

namespace skinlayer::gl {

void delete_program(GLuint name) { glDeleteProgram(name); }
void delete_texture(GLuint name) { glDeleteTextures(1, &name); }
void delete_framebuffer(GLuint name) { glDeleteFramebuffers(1, &name); }
void delete_renderbuffer(GLuint name) { glDeleteRenderbuffers(1, &name); }
void delete_vertex_array(GLuint name) { glDeleteVertexArrays(1, &name); }

Texture create_texture() {
  GLuint name = 0;
  glGenTextures(1, &name);
  return Texture(name);
}
Framebuffer create_framebuffer() {
  GLuint name = 0;
  glGenFramebuffers(1, &name);
  return Framebuffer(name);
}
Renderbuffer create_renderbuffer() {
  GLuint name = 0;
  glGenRenderbuffers(1, &name);
  return Renderbuffer(name);
}
VertexArray create_vertex_array() {
  GLuint name = 0;
  glGenVertexArrays(1, &name);
  return VertexArray(name);
}

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
