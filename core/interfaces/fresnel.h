// Fresnel reflectance of a smooth dielectric boundary, unpolarized light. Inline: the interface albedos and kernels
// evaluate it at every slope and azimuth sample.
#pragma once

#include <cmath>

namespace skinlayer {

// The Fresnel reflectance together with the cosine of the refracted ray, which shares its square root.
// Unpolarized reflectance (Cook & Torrance 1982 form):
//   g = sqrt(eta^2 + c^2 - 1),
//   F = 1/2 ((g - c)/(g + c))^2 [1 + ((c (g + c) - 1)/(c (g - c) + 1))^2],
// with c = |cos| of the angle of incidence on the incident side and eta = n_transmitted / n_incident; by Snell's law
// eta^2 (1 - cos_t^2) = 1 - c^2, so g = eta cos_t. Under total internal reflection (eta^2 + c^2 - 1 <= 0, possible
// only for eta < 1) F = 1 and cos_t = 0. Dimensionless.
struct FresnelRefraction {
  double reflectance;
  double cos_transmitted;
};
inline FresnelRefraction fresnel_refraction(double cos_incident, double eta) {
  const double c = std::abs(cos_incident);
  const double g_squared = eta * eta + c * c - 1.0;
  if (g_squared <= 0.0) return {1.0, 0.0};
  const double g = std::sqrt(g_squared);
  const double a = (g - c) / (g + c);
  const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return {0.5 * a * a * (1.0 + b * b), g / eta};
}

// The reflectance alone.
inline double fresnel_dielectric(double cos_incident, double eta) {
  return fresnel_refraction(cos_incident, eta).reflectance;
}

}  // namespace skinlayer
