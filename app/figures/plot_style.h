// What the plots share: their ink colors, round outer axis values and short tick labels.
#pragma once

#include <cstddef>
#include <string>

#include "app/figures/canvas.h"

namespace skinlayer::figures {

inline constexpr Rgba kPlotBackground{255, 255, 255, 255};
inline constexpr Rgba kPlotInk{30, 30, 30, 255};
inline constexpr Rgba kPlotGrid{205, 205, 205, 255};
inline constexpr Rgba kPlotMuted{110, 110, 110, 255};

// A color per curve index, distinct and readable on white (cycles after 6).
Rgba curve_color(std::size_t index);

// The smallest of {1, 2, 2.5, 5} x 10^k at or above value (value > 0).
double nice_ceiling(double value);

// A short label for an axis value: "%.3g", or a whole number between 1000 and 1e6.
std::string format_axis_value(double value);

}  // namespace skinlayer::figures
