// Every keyboard shortcut and mouse gesture of the previewer, in one table: the key handler reads it and the F1
// help overlay lists it, so the two cannot disagree.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "app/preview/preview_state.h"
#include "app/window/file_panel.h"
#include "app/window/glfw_window.h"

namespace skinlayer {

enum class Action {
  SaveScreenshot,
  Open,
  Save,
  SaveAs,
  Undo,
  Redo,
  ResetMaterial,
  ToggleLogScale,
  ToggleHelp,
  CloseHelp,
  Quit
};

struct Shortcut {
  int key;                // GLFW key code
  bool needs_ctrl;        // only with Ctrl held; otherwise only without it
  bool needs_shift;       // only with Shift held (with Ctrl); otherwise only without it
  std::string_view keys;  // as the help shows it
  std::string_view meaning;
  Action action;
};

struct Gesture {
  std::string_view what;  // e.g. "Ctrl-click a slider"
  std::string_view meaning;
};

std::span<const Shortcut> shortcuts();
std::span<const Gesture> gestures();

// The actions of these key presses, in order. None while a text field has the keyboard (typing), so typing a file
// name never triggers a shortcut.
std::vector<Action> pressed_actions(std::span<const GlfwWindow::KeyPress> presses, bool typing);

// What one frame asks of the previewer, from its panel, its keys and its test script, beyond the toggles they make
// to its state.
struct ActionRequests {
  bool save_screenshot = false;
  bool reset_material = false;
  bool undo = false;
  bool redo = false;
  bool quit = false;
  std::vector<FileCommand> file_commands;  // in the order asked
};

// Makes the actions' toggles in `state` (the lobe plots' log scale, the help overlay) and adds the rest to
// `requests` (file commands after those already there).
void apply_actions(std::span<const Action> actions, PreviewState& state, ActionRequests& requests);

}  // namespace skinlayer
