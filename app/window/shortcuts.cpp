#include "app/window/shortcuts.h"

#define GLFW_INCLUDE_NONE  // no GL header from GLFW: gl_api.h is the one GL header
#include <GLFW/glfw3.h>

#include <array>

namespace skinlayer {
namespace {

constexpr std::array kShortcuts = {
    Shortcut{GLFW_KEY_S, false, "S or Ctrl+S", "save a screenshot (target and path from the Screenshot panel)",
             Action::SaveScreenshot},
    Shortcut{GLFW_KEY_R, false, "R", "reset the material to the paper's default", Action::ResetMaterial},
    Shortcut{GLFW_KEY_L, false, "L", "lobe radius: linear / log", Action::ToggleLogScale},
    Shortcut{GLFW_KEY_F1, false, "F1", "show / hide this help", Action::ToggleHelp},
    Shortcut{GLFW_KEY_ESCAPE, false, "Esc", "hide this help", Action::CloseHelp},
    Shortcut{GLFW_KEY_Q, true, "Ctrl+Q", "quit", Action::Quit},
};

constexpr std::array kGestures = {
    Gesture{"Drag on the sphere", "move the light: the point under the mouse faces it"},
    Gesture{"Hover the lobe plot", "the BSDF in that direction (value under the mouse)"},
    Gesture{"Drag a slider", "change the value"},
    Gesture{"Ctrl-click or right-click a slider", "reset it to its default"},
    Gesture{"Type in the box beside a slider", "exact value; Enter applies it (clamped to the range)"},
    Gesture{"Click the albedo swatch", "color picker for the RGB albedo; right-click resets to white"},
};

}  // namespace

std::span<const Shortcut> shortcuts() { return kShortcuts; }
std::span<const Gesture> gestures() { return kGestures; }

std::vector<Action> pressed_actions(std::span<const GlfwWindow::KeyPress> presses, bool typing) {
  std::vector<Action> actions;
  if (typing) return actions;
  for (const GlfwWindow::KeyPress& press : presses) {
    const bool ctrl = (press.mods & GLFW_MOD_CONTROL) != 0;
    for (const Shortcut& shortcut : kShortcuts) {
      if (shortcut.key == press.key && (ctrl || !shortcut.needs_ctrl)) actions.push_back(shortcut.action);
    }
  }
  return actions;
}

}  // namespace skinlayer
