// The Lambert | Hanrahan-Krueger | Stam comparison picture: one lit sphere per model, rendered offscreen with the
// previewer's renderer (OSMesa), composed side by side with a label under each and a title above.
#pragma once

#include "app/figures/figure_set.h"
#include "app/figures/font.h"
#include "app/render/png_export.h"

namespace skinlayer::figures {

// One sphere per curve of spec (its model, params and albedo_rgb, or its spectral skin), each sphere_size px square,
// light 45 degrees from the view direction on the left. The image is curves x sphere_size wide.
Image draw_model_spheres(const FigureSpec& spec, const Font& font, int sphere_size);

}  // namespace skinlayer::figures
