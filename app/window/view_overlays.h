// The ImGui layer over the GL views: an input-transparent window covering the picture area, with an invisible
// button on each view. On the sphere, dragging moves the light (or the A/B split line, from on it). On the lobe plot:
// angle labels around the plot, ring values, captions and a legend, and the BSDF under the mouse (CPU evaluation with
// brdf_total / btdf_total). It is drawn first each frame and never brought to the front, so the control panel and the
// help stay above it.
#pragma once

#include "app/preview/preview_state.h"
#include "app/preview/view_layout.h"
#include "app/render/scene.h"
#include "app/solution/material_solve.h"
#include "app/solution/sphere_spread.h"

namespace skinlayer {

struct ViewOverlayInput {
  PreviewLayout layout;
  const ColorTables* tables = nullptr;  // the solved material on screen; null before the first result
  LobeView lobes;                       // as drawn this frame (incident angle, scale, peak)
  bool unicode = false;                 // the font has Greek letters and symbols
  const SpreadProfile* profile = nullptr;  // the translucency's profile of the material on screen; null: none
};

// Draws the overlays and handles the mouse; returns true when a drag on the sphere changed the light or, with a
// pinned material, the A/B split line (a drag that starts on the line moves it).
bool view_overlays(const ViewOverlayInput& input, LightState& light, ComparisonState& comparison);

}  // namespace skinlayer
