#include "app/window/shortcuts.h"

#define GLFW_INCLUDE_NONE  // no GL header from GLFW: gl_api.h is the one GL header
#include <GLFW/glfw3.h>

#include <array>

namespace skinlayer {
namespace {

constexpr std::array kShortcuts = {
    Shortcut{GLFW_KEY_O, true, false, "Ctrl+O", "open a material file or a skinlayer PNG", Action::Open},
    Shortcut{GLFW_KEY_S, true, false, "Ctrl+S", "save the material (to its file; else asks for a path)", Action::Save},
    Shortcut{GLFW_KEY_S, true, true, "Ctrl+Shift+S", "save the material as a new file", Action::SaveAs},
    Shortcut{GLFW_KEY_Z, true, false, "Ctrl+Z", "undo a material or light change", Action::Undo},
    Shortcut{GLFW_KEY_Z, true, true, "Ctrl+Shift+Z", "redo", Action::Redo},
    Shortcut{GLFW_KEY_Y, true, false, "Ctrl+Y", "redo", Action::Redo},
    Shortcut{GLFW_KEY_S, false, false, "S", "save a screenshot (target and path from the Screenshot panel)",
             Action::SaveScreenshot},
    Shortcut{GLFW_KEY_R, false, false, "R", "reset the material to the paper's default", Action::ResetMaterial},
    Shortcut{GLFW_KEY_L, false, false, "L", "lobe radius: linear / log", Action::ToggleLogScale},
    Shortcut{GLFW_KEY_F1, false, false, "F1", "show / hide this help", Action::ToggleHelp},
    Shortcut{GLFW_KEY_ESCAPE, false, false, "Esc", "hide this help", Action::CloseHelp},
    Shortcut{GLFW_KEY_Q, true, false, "Ctrl+Q", "quit (asks first when the material has unsaved changes)",
             Action::Quit},
};

constexpr std::array kGestures = {
    Gesture{"Drag on the sphere", "move the light: the point under the mouse faces it"},
    Gesture{"Hover the lobe plot", "the BSDF in that direction (value under the mouse)"},
    Gesture{"Drag a slider", "change the value"},
    Gesture{"Ctrl-click or right-click a slider", "reset it to its default"},
    Gesture{"Type in the box beside a slider", "exact value; Enter applies it (clamped to the range)"},
    Gesture{"Click the albedo swatch", "color picker for the RGB albedo; right-click resets to white"},
    Gesture{"Drop a file on the window", "open a material file or a skinlayer PNG's material"},
};

}  // namespace

std::span<const Shortcut> shortcuts() { return kShortcuts; }
std::span<const Gesture> gestures() { return kGestures; }

std::vector<Action> pressed_actions(std::span<const GlfwWindow::KeyPress> presses, bool typing) {
  std::vector<Action> actions;
  if (typing) return actions;
  for (const GlfwWindow::KeyPress& press : presses) {
    const bool ctrl = (press.mods & GLFW_MOD_CONTROL) != 0;
    const bool shift = (press.mods & GLFW_MOD_SHIFT) != 0;
    for (const Shortcut& shortcut : kShortcuts) {
      // F1 and Esc work with any modifier; letters only with exactly the modifiers listed.
      const bool letter = shortcut.key >= GLFW_KEY_A && shortcut.key <= GLFW_KEY_Z;
      const bool modifiers_match = !letter || (ctrl == shortcut.needs_ctrl && (!ctrl || shift == shortcut.needs_shift));
      if (shortcut.key == press.key && modifiers_match) actions.push_back(shortcut.action);
    }
  }
  return actions;
}

void apply_actions(std::span<const Action> actions, PreviewState& state, ActionRequests& requests) {
  for (const Action action : actions) {
    switch (action) {
      case Action::SaveScreenshot:
        requests.save_screenshot = true;
        break;
      case Action::ResetMaterial:
        requests.reset_material = true;
        break;
      case Action::ToggleLogScale:
        state.view.log_lobes = !state.view.log_lobes;
        break;
      case Action::ToggleHelp:
        state.show_help = !state.show_help;
        break;
      case Action::CloseHelp:
        state.show_help = false;
        break;
      case Action::Quit:
        requests.quit = true;
        break;
      case Action::Open:
        requests.file_commands.push_back({FileCommand::Kind::Open, ""});
        break;
      case Action::Save:
        requests.file_commands.push_back({FileCommand::Kind::Save, ""});
        break;
      case Action::SaveAs:
        requests.file_commands.push_back({FileCommand::Kind::SaveAs, ""});
        break;
      case Action::Undo:
        requests.undo = true;
        break;
      case Action::Redo:
        requests.redo = true;
        break;
    }
  }
}

}  // namespace skinlayer
