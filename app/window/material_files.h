// The previewer's material-file workflow over the material on the controls: open (a material file or a skinlayer
// PNG, from the chooser, the recent list or a drop), save, save as, presets, the recent-files list and the
// unsaved-changes question before anything replaces the material or the window closes. The UI (file_panel.h)
// reports commands; this runs them. Errors never throw: they become the message shown in the File section.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/preview/material_session.h"
#include "app/solution/material_solve.h"
#include "app/window/file_panel.h"
#include "app/window/window_options.h"

namespace skinlayer {

class MaterialFiles {
 public:
  // `recent_list`: where the recent files are kept (recent_files_path()), or nullopt for none.
  MaterialFiles(MaterialSession session, std::optional<std::filesystem::path> recent_list);

  // Runs a command on `material`, which an open or a preset replaces. Returns true when the window may close now
  // (a Quit with nothing unsaved, or whose question was answered).
  bool run(const FileCommand& command, ColorMaterial& material);

  // The window's close request: true when it may close; otherwise the question is asked first.
  bool may_close(const ColorMaterial& material);

  FileDialog& dialog() { return dialog_; }
  const MaterialSession& session() const { return session_; }
  FileSectionInput section_input(const ColorMaterial& material) const;

 private:
  void after_answer(bool saved, ColorMaterial& material, bool& close);
  std::string chooser_start() const;
  void open(const std::string& path, ColorMaterial& material);
  void load_preset(const std::string& name, ColorMaterial& material);
  void save(std::string path, const ColorMaterial& material);
  void remember(const std::string& path);

  MaterialSession session_;
  FileDialog dialog_;
  FileCommand after_save_;  // what a Save answering the question interrupted, while its path is chosen
  bool quit_answered_ = false;
  std::string message_;
  std::vector<std::string> preset_names_;
  std::optional<std::filesystem::path> recent_list_;
  std::vector<std::string> recent_;
};

// The session the window opens with: the material file given with --material (flags given next to it count as
// opened, not as unsaved edits), or an untitled one named for its preset.
MaterialSession initial_session(const WindowOptions& options);

}  // namespace skinlayer
