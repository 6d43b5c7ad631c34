#include "app/material/exact_transparency.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/material.h"

namespace skinlayer {

std::optional<double> exact_transparency(double tau) {
  const double transparency = std::exp(-tau);
  for (int digits = 1; digits <= 17; ++digits) {
    char text[40];
    const int length = std::snprintf(text, sizeof text, "%.*g", digits, transparency);
    double read_back = 0.0;
    std::from_chars(text, text + length, read_back);  // locale-independent, unlike strtod
    if (optical_depth_from_transparency(read_back) == tau) return read_back;
  }
  return std::nullopt;
}

}  // namespace skinlayer
