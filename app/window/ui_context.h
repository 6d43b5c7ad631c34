// Dear ImGui for one GLFW window, as an RAII object: creates the ImGui context and the GLFW + OpenGL3 backends
// (compiled from libimgui-dev's sources, calling gl* through <GL/glcorearb.h>), and destroys them in reverse order.
// The window's GL context must be current for its whole life. No imgui.ini is read or written.
#pragma once

struct GLFWwindow;
struct ImFont;

namespace skinlayer {

class ImGuiSession {
 public:
  // content_scale: the monitor's content scale (1 on a plain display); fonts and sizes are scaled by it.
  ImGuiSession(GLFWwindow* window, float content_scale);
  ~ImGuiSession();

  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;

  void new_frame() const;  // backends, then ImGui::NewFrame
  void render() const;     // ImGui::Render and draw into the bound framebuffer

  // True when the font has the Greek letters and symbols the labels use (σ, η, τ, Ω, …, ∞); false with ImGui's
  // built-in font (when DejaVu Sans is not installed), in which case labels use ASCII names.
  bool unicode_labels() const { return unicode_; }
  float scale() const { return scale_; }

 private:
  float scale_ = 1.0f;
  bool unicode_ = false;
};

}  // namespace skinlayer
