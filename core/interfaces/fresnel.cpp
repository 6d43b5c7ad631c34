#include "core/interfaces/fresnel.h"

#include <cmath>

namespace skinlayer {

double fresnel_dielectric(double cos_incident, double eta) {
  const double c = std::abs(cos_incident);
  const double g_squared = eta * eta + c * c - 1.0;
  if (g_squared <= 0.0) return 1.0;
  const double g = std::sqrt(g_squared);
  const double a = (g - c) / (g + c);
  const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

}  // namespace skinlayer
