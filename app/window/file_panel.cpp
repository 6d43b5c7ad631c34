#include "app/window/file_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace skinlayer {
namespace {

namespace fs = std::filesystem;

const ImVec4 kDimColor{0.7f, 0.7f, 0.7f, 1.0f};
constexpr std::size_t kMaxListed = 400;  // entries of one folder shown in the chooser

const char* dialog_title(FileDialog::Kind kind) {
  switch (kind) {
    case FileDialog::Kind::Open:
      return "Open a material file or a skinlayer PNG";
    case FileDialog::Kind::SaveAs:
      return "Save the material as";
    case FileDialog::Kind::ConfirmDiscard:
      return "Unsaved changes";
    case FileDialog::Kind::None:
      break;
  }
  return "";
}

// The folder the path field points into: itself if it is a folder, else its parent, else the current folder.
fs::path listed_folder(const std::string& path) {
  std::error_code error;
  if (path.empty()) return fs::current_path(error);
  const fs::path typed(path);
  if (fs::is_directory(typed, error)) return typed;
  const fs::path parent = typed.parent_path();
  return parent.empty() ? fs::current_path(error) : parent;
}

// Sub-folders first, then the material (.json) and picture (.png) files, each sorted by name.
std::vector<fs::directory_entry> chooser_entries(const fs::path& folder) {
  std::vector<fs::directory_entry> folders, files;
  std::error_code error;
  for (fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, error), end;
       !error && it != end && folders.size() + files.size() < kMaxListed; it.increment(error)) {
    const fs::path& path = it->path();
    if (path.filename().string().starts_with(".")) continue;
    std::error_code kind_error;
    if (it->is_directory(kind_error)) {
      folders.push_back(*it);
    } else if (path.extension() == ".json" || path.extension() == ".png") {
      files.push_back(*it);
    }
  }
  const auto by_name = [](const fs::directory_entry& a, const fs::directory_entry& b) { return a.path() < b.path(); };
  std::sort(folders.begin(), folders.end(), by_name);
  std::sort(files.begin(), files.end(), by_name);
  folders.insert(folders.end(), files.begin(), files.end());
  return folders;
}

// The path field and the folder's list; returns true when the user confirms (button, Enter or double-click).
bool path_chooser(std::string& path, const char* confirm_label) {
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 32.0f);
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  bool confirmed = ImGui::InputText("##file", &path, ImGuiInputTextFlags_EnterReturnsTrue);
  const fs::path folder = listed_folder(path);
  ImGui::TextColored(kDimColor, "%s", folder.string().c_str());
  if (ImGui::BeginListBox("##entries", ImVec2(ImGui::GetFontSize() * 32.0f, ImGui::GetFontSize() * 14.0f))) {
    if (folder.has_parent_path() && folder != folder.root_path() && ImGui::Selectable("../")) {
      path = folder.parent_path().string() + "/";
    }
    for (const fs::directory_entry& entry : chooser_entries(folder)) {
      std::error_code error;
      const bool is_folder = entry.is_directory(error);
      const std::string label = entry.path().filename().string() + (is_folder ? "/" : "");
      const bool selected = !is_folder && entry.path() == fs::path(path);
      if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
        path = entry.path().string() + (is_folder ? "/" : "");
        if (!is_folder && ImGui::IsMouseDoubleClicked(0)) confirmed = true;
      }
    }
    ImGui::EndListBox();
  }
  confirmed |= ImGui::Button(confirm_label);
  return confirmed;
}

}  // namespace

FileSectionResult file_section(const FileSectionInput& input) {
  FileSectionResult result;
  ImGui::TextUnformatted(input.title.c_str());
  if (input.unsaved) {
    ImGui::SameLine();
    ImGui::TextColored(kDimColor, "(unsaved changes)");
  }
  if (ImGui::Button("Open... (Ctrl+O)")) result.command.kind = FileCommand::Kind::Open;
  ImGui::SameLine();
  if (ImGui::Button("Save (Ctrl+S)")) result.command.kind = FileCommand::Kind::Save;
  ImGui::SameLine();
  if (ImGui::Button("Save as...")) result.command.kind = FileCommand::Kind::SaveAs;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9.0f);
  if (ImGui::BeginCombo("##preset", "Presets", ImGuiComboFlags_HeightLarge)) {
    for (const std::string& name : input.presets) {
      if (ImGui::Selectable(name.c_str())) result.command = {FileCommand::Kind::LoadPreset, name};
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9.0f);
  if (ImGui::BeginCombo("##recent", "Recent", ImGuiComboFlags_HeightLarge)) {
    if (input.recent.empty()) ImGui::TextColored(kDimColor, "no recent files");
    for (const std::string& path : input.recent) {
      if (ImGui::Selectable(path.c_str())) result.command = {FileCommand::Kind::OpenPath, path};
    }
    ImGui::EndCombo();
  }
  ImGui::BeginDisabled(input.undo_steps == 0);
  result.undo = ImGui::Button("Undo (Ctrl+Z)");
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(input.redo_steps == 0);
  result.redo = ImGui::Button("Redo (Ctrl+Y)");
  ImGui::EndDisabled();
  if (!input.message.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kDimColor, "%s", input.message.c_str());
    ImGui::PopTextWrapPos();
  }
  return result;
}

FileCommand file_dialogs(FileDialog& dialog) {
  FileCommand command;
  if (dialog.kind == FileDialog::Kind::None) return command;
  const char* title = dialog_title(dialog.kind);
  if (!ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  bool open = true;
  if (!ImGui::BeginPopupModal(title, &open, ImGuiWindowFlags_AlwaysAutoResize)) {
    if (!open) dialog = {};
    return command;
  }
  bool close = false;
  switch (dialog.kind) {
    case FileDialog::Kind::Open:
      if (path_chooser(dialog.path, "Open")) {
        command = {FileCommand::Kind::OpenPath, dialog.path};
        close = true;
      }
      break;
    case FileDialog::Kind::SaveAs:
      if (path_chooser(dialog.path, "Save")) {
        command = {FileCommand::Kind::SaveAs, dialog.path};
        close = true;
      }
      break;
    case FileDialog::Kind::ConfirmDiscard:
      ImGui::TextUnformatted("The material has unsaved changes.");
      if (ImGui::Button("Save")) {
        command = {FileCommand::Kind::Save, ""};
        close = true;
      }
      ImGui::SameLine();
      if (ImGui::Button("Discard them")) {
        command = {FileCommand::Kind::Discard, ""};
        close = true;
      }
      ImGui::SameLine();
      break;
    case FileDialog::Kind::None:
      break;
  }
  if (dialog.kind != FileDialog::Kind::ConfirmDiscard) ImGui::SameLine();
  if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    close = true;
    command = {};
  }
  if (close || !open) {
    ImGui::CloseCurrentPopup();
    // ConfirmDiscard keeps its follow-up for the previewer to run; the others are done.
    if (command.kind != FileCommand::Kind::Save && command.kind != FileCommand::Kind::Discard) dialog = {};
  }
  ImGui::EndPopup();
  return command;
}

}  // namespace skinlayer
