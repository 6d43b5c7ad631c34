#include "app/window/help_overlay.h"

#include <imgui.h>

#include <string>

#include "app/window/shortcuts.h"

namespace skinlayer {
namespace {

void two_columns(std::string_view left, std::string_view right) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(left.data(), left.data() + left.size());
  ImGui::TableSetColumnIndex(1);
  ImGui::TextUnformatted(right.data(), right.data() + right.size());
}

}  // namespace

void draw_help_overlay(bool& open) {
  if (!open) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(viewport->GetCenter(), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.92f);
  const ImGuiWindowFlags flags =
      ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse;
  if (ImGui::Begin("Help (F1)", &open, flags)) {
    constexpr ImGuiTableFlags table = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV;
    ImGui::TextUnformatted("Keys");
    if (ImGui::BeginTable("keys", 2, table)) {
      for (const Shortcut& shortcut : shortcuts()) two_columns(shortcut.keys, shortcut.meaning);
      ImGui::EndTable();
    }
    ImGui::Spacing();
    ImGui::TextUnformatted("Mouse");
    if (ImGui::BeginTable("mouse", 2, table)) {
      for (const Gesture& gesture : gestures()) two_columns(gesture.what, gesture.meaning);
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

}  // namespace skinlayer
