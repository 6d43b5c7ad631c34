// The previewer's test hook (--test-actions, app/window/window_options.h) for the edits that change its state alone
// and need no window: the sliders (set, drag), the layers panel's buttons (layer), the Skin section's (skin), the
// lighting controls (lighting) and the A/B split (split). The previewer runs the other actions (undo, save, export,
// pin, ...) itself. Plain functions on PreviewState, so that they are tested without a window.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "app/preview/preview_state.h"

namespace skinlayer {

// Applies the action `verb argument` to `state` when verb is one of set, layer, skin, lighting, view and split, and
// returns true; returns false for any other verb. Throws std::runtime_error ("test action: ...") for a malformed
// argument or number (named, in one line).
//   set NAME VALUE        a slider: sigma, eta, g, T, albedo (grey); with a skin, a skin slider by its key
//   layer add | remove I | up I | down I      the layers panel's buttons (I 1-based)
//   skin on | off         "Make it a skin" / back to a layer
//   lighting env NAME|none | env-rotate DEG | env-ev EV | light on|off
//   view light-theta DEG | light-phi DEG | radius MM | translucency on|off
//   split FRACTION        the A/B comparison's split line
bool apply_scripted_edit(PreviewState& state, std::string_view verb, std::string_view argument);

// "drag NAME V1,V2,...": the slider NAME dragged through the values, one a frame without waiting for the solves, as a
// mouse drag would (one undo step when it ends); the arguments of the "set" edits it makes, in order. Throws as
// apply_scripted_edit for a value that is not a number.
std::vector<std::string> drag_steps(std::string_view argument);

}  // namespace skinlayer
