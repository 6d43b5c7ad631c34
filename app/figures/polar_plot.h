// A polar lobe plot in the plane of incidence, as in Stam's figures: reflection above the surface line,
// transmission below, light arriving from the upper left (so the forward side, phi = 180 degrees, is on the right),
// circles of equal value and rays every 15 degrees, angle labels, one colored curve per parameter value with a
// legend, and a title with the fixed parameter values.
#pragma once

#include <string>
#include <vector>

#include "app/figures/canvas.h"
#include "app/figures/font.h"
#include "app/figures/plot_style.h"
#include "app/render/png_export.h"

namespace skinlayer::figures {

// One lobe sample: the outgoing direction as a signed angle in degrees, in [-90, 90] (negative: the back side,
// phi = 0; positive: the forward side, phi = 180), measured from the upper normal for reflection and from the lower
// normal for transmission; and the plotted value (1/sr, or relative after rescaling; >= 0).
struct LobeSample {
  double signed_theta_deg = 0.0;
  double value = 0.0;
};

struct PolarCurve {
  std::string label;                     // legend text, e.g. "σ = 0.3"
  Rgba color;
  double theta_i_deg = 45.0;             // the incident direction, drawn as a short ray
  std::vector<LobeSample> reflection;    // in order of signed angle; may be empty
  std::vector<LobeSample> transmission;  // likewise
};

struct PolarPlot {
  std::string title;     // first title line
  std::string subtitle;  // second line: the fixed parameters
  std::string unit;      // the radial axis, e.g. "1/sr" or "relative to the peak"
  std::vector<PolarCurve> curves;
  int size = 640;        // the square image's side [px]
  int log_decades = 0;   // 0: radius linear in the value; n > 0: log10 of the value over n decades below the outer
                         // circle (values further down sit at the centre)
  bool separate_scales = false;  // reflection and transmission each scaled to their own outer value
};

// Draws the plot. The outer circle is a round value at or above the largest sample of all curves (of each half with
// separate_scales; a power of ten on the log scale), and the circles are labelled with their values (the
// transmission half's below the surface line when the scales are separate).
Image draw_polar_plot(const PolarPlot& plot, const Font& font);

}  // namespace skinlayer::figures
