// The previewer's material files in the UI: the File section of the control panel (open, save, save as, presets,
// recent files) and its modal dialogs, drawn inside ImGui (a path field over a list of the folder's material and
// PNG files; no external dialog program). Immediate mode: the dialogs' state is the FileDialog value the previewer
// owns; these functions draw it and report what the user asked for.
#pragma once

#include <string>
#include <vector>

namespace skinlayer {

// What the user asked for this frame.
struct FileCommand {
  enum class Kind { None, Open, Save, SaveAs, OpenPath, LoadPreset, Discard, Quit };
  Kind kind = Kind::None;
  std::string argument;  // OpenPath: the path; LoadPreset: the preset's name
};

// A dialog on screen, or none.
struct FileDialog {
  enum class Kind { None, Open, SaveAs, ConfirmDiscard };
  Kind kind = Kind::None;
  std::string path;           // the path field (Open, SaveAs)
  FileCommand after_discard;  // ConfirmDiscard: what runs once the unsaved changes are saved or discarded
};

struct FileSectionInput {
  std::string title;  // the open file's name (session_name)
  bool unsaved = false;
  std::vector<std::string> presets;  // names
  std::vector<std::string> recent;   // paths, newest first
  std::string message;               // the last open/save outcome or error
  std::size_t undo_steps = 0, redo_steps = 0;
};

// The File section (inside the control panel's window). Undo and redo are reported as Kind::None with
// `undo`/`redo` set, since they are not file commands.
struct FileSectionResult {
  FileCommand command;
  bool undo = false;
  bool redo = false;
};
FileSectionResult file_section(const FileSectionInput& input);

// The modal dialog of `dialog`, if any (call once a frame, outside other windows). Returns the command it
// confirms: OpenPath, SaveAs (argument: the path), or for ConfirmDiscard, Save (save first, then go on) or Discard
// (go on without saving); closing or Cancel resets the dialog and returns None.
FileCommand file_dialogs(FileDialog& dialog);

}  // namespace skinlayer
