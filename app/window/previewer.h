// The previewer's main loop: one GLFW window with the control panel on the left and the renderer's sphere and lobe
// plot on the right, the solver on a worker thread, and screenshots through save_screenshot().
#pragma once

#include <ostream>

#include "app/window/window_options.h"

namespace skinlayer {

// Opens the window and runs until it is closed, or, with options.capture_path, until the material is solved and
// the whole window has been saved there (at framebuffer resolution; "wrote FILE (WxH)" goes to out). Returns the
// exit status, 0. Throws NoDisplayError without a display, and std::runtime_error when the window cannot be made
// or, in capture mode, when the material cannot be solved or the screenshot cannot be written.
int run_previewer(const WindowOptions& options, std::ostream& out);

}  // namespace skinlayer
