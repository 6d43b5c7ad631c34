// The translucency's profile plot (issue 43): the material's reflectance profile R(r), log R per channel against r in
// mm, as an inset in the lower right of the lobe plots, drawn with ImGui over the GL views.
#pragma once

#include <imgui.h>

#include "app/preview/view_layout.h"
#include "app/solution/sphere_spread.h"

namespace skinlayer {

// Four decades below the peak, out to the radius where every channel has fallen below them (0.5 to 20 mm).
void draw_profile_plot(ImDrawList& draw, const Rect& plots, const SpreadProfile& profile);

}  // namespace skinlayer
