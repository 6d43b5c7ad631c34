// The unscattered part of the layer BTDF (core/unscattered_light.h) in the plane of incidence, sampled for the lobe
// plot's one incident angle: a 1-D texture on coordinates centred on the lobe, because the two-interface part is a
// quadrature per direction (too slow per pixel) and its lobe can be narrower than a degree.
//
// Samples lie at signed exit angles s (radians; s > 0 forward, phi = pi; s < 0 back, phi = 0) spaced as
//   s = centre + scale sinh(u),   u uniform in [u_min, u_max],  s spanning [-pi/2, pi/2],
// finest (scale du ~ 1e-4 rad for 1024 samples) at the flat interfaces' exit direction, 1 degree apart at grazing.
// shaders/unscattered.glsl reads it with linear filtering; unscattered_plane_value() is the CPU twin.
#pragma once

#include <vector>

#include "core/unscattered_light.h"

namespace skinlayer {

struct UnscatteredPlane {
  double centre = 0.0;  // the flat interfaces' exit angle, signed [rad]
  double scale = 0.01;  // [rad]
  double u_min = -1.0;
  double u_max = 1.0;
  std::vector<float> btdf;  // [1/sr] at u_k = u_min + k (u_max - u_min) / (n - 1); empty when there is none
};

UnscatteredPlane sample_unscattered_plane(const UnscatteredLight& light, double theta_i, int samples = 1024);

// The texture's value at signed exit angle s: linear interpolation in u, as the GPU filters it.
double unscattered_plane_value(const UnscatteredPlane& plane, double signed_theta_o);

}  // namespace skinlayer
