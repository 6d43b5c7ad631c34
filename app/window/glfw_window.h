// The GLFW library session and the previewer's one window with a current OpenGL 3.3 core context, as one RAII
// object: constructing it initializes GLFW and opens the window; destroying it closes the window and terminates
// GLFW. GLFW's error callback is a silent one, so GLFW never prints; failures become exceptions with one-line
// messages.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

struct GLFWwindow;

namespace skinlayer {

// There is no display to open a window on (no DISPLAY, or the X server refused). what() is one line that names
// GLFW's reason and points to `skinlayer render`.
class NoDisplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class GlfwWindow {
 public:
  // Opens a window of the given size in screen coordinates, scaled by the monitor's content scale where the
  // platform does that (GLFW_SCALE_TO_MONITOR), and makes its context current with vsync on.
  // Throws NoDisplayError if GLFW cannot initialize, std::runtime_error if the window or context cannot be created.
  GlfwWindow(int width, int height, const std::string& title);
  ~GlfwWindow();

  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close() const;
  void cancel_close() const;  // the user's close request is answered by a question first
  void swap_buffers() const;
  void set_title(const std::string& title);  // only calls GLFW when the title changes

  // Key presses since the last call, in order (repeats excluded). They are queued by a GLFW key callback installed
  // before ImGui's, which chains to it, so a press and release within one frame are never lost (ImGui 1.86 reads
  // only the key state at the start of a frame).
  struct KeyPress {
    int key;   // GLFW_KEY_*
    int mods;  // GLFW_MOD_* bits
  };
  std::vector<KeyPress> take_key_presses();

  // Paths of files dropped onto the window since the last call, in order.
  std::vector<std::string> take_dropped_paths();

  std::array<int, 2> framebuffer_size() const;  // pixels
  std::array<int, 2> window_size() const;       // screen coordinates (ImGui's units)
  float content_scale() const;                  // the larger of GLFW's x and y content scale; 1 on a plain display

 private:
  // Initializes GLFW in its constructor and terminates it in its destructor, so it outlives the window.
  class Library {
   public:
    Library();
    ~Library();
    Library(const Library&) = delete;
    Library& operator=(const Library&) = delete;
  };

  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void on_drop(GLFWwindow* window, int count, const char** paths);

  Library library_;
  GLFWwindow* window_ = nullptr;  // owned: glfwDestroyWindow in the destructor; its user pointer is this
  std::vector<KeyPress> key_presses_;
  std::vector<std::string> dropped_paths_;
  std::string title_;
};

// Wakes a thread blocked in glfwWaitEvents*; callable from any thread while GLFW is initialized.
void post_empty_event();

// Waits for events at most timeout seconds (0: poll without waiting).
void wait_events(double timeout_seconds);

}  // namespace skinlayer
