#include "app/window/glfw_window.h"

#define GLFW_INCLUDE_NONE  // no GL header from GLFW: gl_api.h is the one GL header
#include <GLFW/glfw3.h>

#include <algorithm>
#include <utility>

namespace skinlayer {
namespace {

// GLFW reports errors through this callback as well as through glfwGetError; the messages are read from
// glfwGetError where they matter, so the callback prints nothing.
void ignore_glfw_error(int /*code*/, const char* /*description*/) {}

std::string last_glfw_error() {
  const char* description = nullptr;
  if (glfwGetError(&description) != GLFW_NO_ERROR && description != nullptr) return description;
  return "unknown reason";
}

}  // namespace

GlfwWindow::Library::Library() {
  glfwSetErrorCallback(ignore_glfw_error);
  if (glfwInit() != GLFW_TRUE) {
    throw NoDisplayError("no display available (" + last_glfw_error() +
                         "); render headless with: skinlayer render -o out.png");
  }
}

GlfwWindow::Library::~Library() { glfwTerminate(); }

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    throw std::runtime_error("cannot open an OpenGL 3.3 core window (" + last_glfw_error() +
                             "); render headless with: skinlayer render -o out.png");
  }
  glfwSetWindowUserPointer(window_, this);  // GlfwWindow is not movable: this stays valid
  glfwSetKeyCallback(window_, on_key);
  glfwSetDropCallback(window_, on_drop);
  title_ = title;
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
}

void GlfwWindow::on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
  if (action != GLFW_PRESS) return;
  auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
  if (self != nullptr) self->key_presses_.push_back(KeyPress{key, mods});
}

std::vector<GlfwWindow::KeyPress> GlfwWindow::take_key_presses() { return std::exchange(key_presses_, {}); }

void GlfwWindow::on_drop(GLFWwindow* window, int count, const char** paths) {
  auto* self = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
  if (self == nullptr) return;
  for (int k = 0; k < count; ++k) self->dropped_paths_.emplace_back(paths[k]);
}

std::vector<std::string> GlfwWindow::take_dropped_paths() { return std::exchange(dropped_paths_, {}); }

void GlfwWindow::set_title(const std::string& title) {
  if (title == title_) return;
  title_ = title;
  glfwSetWindowTitle(window_, title.c_str());
}

GlfwWindow::~GlfwWindow() {
  if (window_ != nullptr) glfwDestroyWindow(window_);
}

bool GlfwWindow::should_close() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void GlfwWindow::request_close() const { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void GlfwWindow::cancel_close() const { glfwSetWindowShouldClose(window_, GLFW_FALSE); }
void GlfwWindow::swap_buffers() const { glfwSwapBuffers(window_); }

std::array<int, 2> GlfwWindow::framebuffer_size() const {
  std::array<int, 2> size{};
  glfwGetFramebufferSize(window_, &size[0], &size[1]);
  return size;
}

std::array<int, 2> GlfwWindow::window_size() const {
  std::array<int, 2> size{};
  glfwGetWindowSize(window_, &size[0], &size[1]);
  return size;
}

float GlfwWindow::content_scale() const {
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window_, &x, &y);
  const float scale = std::max(x, y);
  return scale > 0.0f ? scale : 1.0f;
}

void post_empty_event() { glfwPostEmptyEvent(); }

void wait_events(double timeout_seconds) {
  if (timeout_seconds > 0.0) {
    glfwWaitEventsTimeout(timeout_seconds);
  } else {
    glfwPollEvents();
  }
}

}  // namespace skinlayer
