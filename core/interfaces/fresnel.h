// Fresnel reflectance of a smooth dielectric boundary, unpolarized light.
#pragma once

namespace skinlayer {

// Unpolarized Fresnel reflectance (Cook & Torrance 1982 form):
//   g = sqrt(eta^2 + c^2 - 1),
//   F = 1/2 ((g - c)/(g + c))^2 [1 + ((c (g + c) - 1)/(c (g - c) + 1))^2],
// with c = |cos| of the angle of incidence on the incident side and eta = n_transmitted / n_incident.
// Returns 1 under total internal reflection (eta^2 + c^2 - 1 <= 0, possible only for eta < 1). Dimensionless.
double fresnel_dielectric(double cos_incident, double eta);

}  // namespace skinlayer
