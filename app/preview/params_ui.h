// ImGui controls for the previewer's values. The material's rows come from core's parameter_table() (label, range,
// default and meaning); the light and view rows follow the same pattern. ImGui must be inside a frame and a window.
//
// Every slider row is: label, slider, typed-entry box.
//  - Drag the slider to change the value.
//  - Ctrl-click or right-click the slider to reset it to its default (ImGui's own Ctrl-click text entry is turned
//    off on these sliders, so Ctrl-click can reset as the issue asks).
//  - Type a value into the box beside it and press Enter for an exact value; it is clamped to the range.
//  - Hovering the label shows the parameter's meaning, range and default.
#pragma once

#include "app/preview/preview_state.h"

namespace skinlayer {

// unicode: label with the table's symbols (σ, η, Ω, …) rather than the flag names, when the font has the glyphs.
// Each returns true when it changed a value this frame. A skin's material shows its top interface only (its layers
// are in the Skin section, app/preview/skin_ui.h).
bool material_controls(ColorMaterial& material, bool unicode);
bool light_controls(LightState& light, bool unicode);
bool view_controls(ViewOptions& view);
// The environment (none, a built-in, or a typed .hdr path loaded by its button), its rotation, EV and background,
// the directional light's switch and the tone map. `samples`: the estimate's samples per pixel so far (shown).
bool lighting_controls(LightingState& lighting, int samples);

}  // namespace skinlayer
