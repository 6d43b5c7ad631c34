// The previewer's test hook (--test-actions, app/window/window_options.h) for the edits that change its state alone
// and need no window: the sliders (set), the layers panel's buttons (layer), the Skin section's (skin), the
// lighting controls (lighting) and the A/B split (split). The previewer runs the other actions (undo, save, export,
// pin, ...) itself. Plain functions on PreviewState, so that they are tested without a window.
#pragma once

#include <string_view>

#include "app/preview/preview_state.h"

namespace skinlayer {

// Applies the action `verb argument` to `state` when verb is one of set, layer, skin, lighting and split, and
// returns true; returns false for any other verb. Throws std::runtime_error ("test action: ...") for a malformed
// argument.
//   set NAME VALUE        a slider: sigma, eta, g, T, albedo (grey); with a skin, a skin slider by its key
//   layer add | remove I | up I | down I      the layers panel's buttons (I 1-based)
//   skin on | off         "Make it a skin" / back to a layer
//   lighting env NAME|none | env-rotate DEG | env-ev EV | light on|off
//   split FRACTION        the A/B comparison's split line
bool apply_scripted_edit(PreviewState& state, std::string_view verb, std::string_view argument);

}  // namespace skinlayer
