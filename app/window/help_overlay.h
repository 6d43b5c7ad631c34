// The F1 help overlay: a window in the middle of the screen that lists every shortcut and gesture of shortcuts.h.
#pragma once

namespace skinlayer {

// Draws the overlay while open is true (ImGui must be inside a frame); its close button sets open to false.
void draw_help_overlay(bool& open);

}  // namespace skinlayer
