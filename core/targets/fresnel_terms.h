// Two Fresnel terms the renderers' shaders share (core/targets/), written once:
//   normal_reflectance(eta) = ((eta - 1) / (eta + 1))^2, a dielectric's reflectance at normal incidence (Fresnel's
//                             equations at theta = 0, unpolarized; dimensionless): F0 of Schlick's approximation;
//   schlick_weight(c)       = (1 - c)^5, Schlick 1994's weight of the blend from F0 toward F90 at the cosine c
//                             (clamped to [0, 1]).
#pragma once

#include <algorithm>
#include <cmath>

namespace skinlayer {

inline double normal_reflectance(double eta) { return (eta - 1.0) * (eta - 1.0) / ((eta + 1.0) * (eta + 1.0)); }

inline double schlick_weight(double cosine) { return std::pow(1.0 - std::clamp(cosine, 0.0, 1.0), 5.0); }

}  // namespace skinlayer
