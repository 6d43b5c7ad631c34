#include "app/window/ui_context.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <array>
#include <filesystem>
#include <stdexcept>

namespace skinlayer {
namespace {

// Latin-1, Greek, the ellipsis, superscripts, arrows and infinity: what the labels and readouts print.
constexpr std::array<ImWchar, 13> kGlyphRanges = {
    0x0020, 0x00FF, 0x0370, 0x03FF, 0x2026, 0x2026, 0x2070, 0x209F, 0x2190, 0x21FF, 0x221E, 0x221E, 0,
};

constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // fonts-dejavu-core
constexpr float kFontPixels = 15.0f;                                                  // DejaVu Sans at content scale 1
constexpr float kBuiltinPixels = 13.0f;                                               // ImGui's ProggyClean

}  // namespace

ImGuiSession::ImGuiSession(GLFWwindow* window, float content_scale) : scale_(content_scale) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui::GetStyle().ScaleAllSizes(scale_);

  std::error_code error;
  if (std::filesystem::exists(kFontPath, error)) {
    ImFontConfig config;
    config.OversampleH = 2;
    unicode_ = io.Fonts->AddFontFromFileTTF(kFontPath, kFontPixels * scale_, &config, kGlyphRanges.data()) != nullptr;
  }
  if (!unicode_) {
    ImFontConfig config;
    config.SizePixels = kBuiltinPixels * scale_;
    io.Fonts->AddFontDefault(&config);
  }

  if (!ImGui_ImplGlfw_InitForOpenGL(window, true)) {
    ImGui::DestroyContext();
    throw std::runtime_error("cannot start the ImGui GLFW backend");
  }
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    throw std::runtime_error("cannot start the ImGui OpenGL3 backend");
  }
}

ImGuiSession::~ImGuiSession() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiSession::new_frame() const {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiSession::render() const {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace skinlayer
