#include "app/figures/plot_style.h"

#include <array>
#include <cmath>
#include <cstdio>

namespace skinlayer::figures {

double nice_ceiling(double value) {
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  for (double step : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (step * decade >= value * (1.0 - 1e-12)) return step * decade;
  }
  return 10.0 * decade;
}

std::string format_axis_value(double value) {
  char text[32];
  std::snprintf(text, sizeof text, value >= 1000.0 && value < 1e6 ? "%.0f" : "%.3g", value);
  return text;
}

Rgba curve_color(std::size_t index) {
  constexpr std::array<Rgba, 6> kColors = {{{31, 119, 180, 255},
                                            {255, 127, 14, 255},
                                            {44, 160, 44, 255},
                                            {214, 39, 40, 255},
                                            {148, 103, 189, 255},
                                            {140, 86, 75, 255}}};
  return kColors[index % kColors.size()];
}

}  // namespace skinlayer::figures
