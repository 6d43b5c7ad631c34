// The unscattered part of the layer BTDF (core/unscattered/unscattered_light.h) in the plane of incidence, sampled for
// the lobe plot's one incident angle: a 1-D texture on coordinates centred on the lobe, because the two-interface part is a
// quadrature per direction (too slow per pixel) and its lobe can be narrower than a degree.
//
// Samples lie at signed exit angles s (radians; s > 0 forward, phi = pi; s < 0 back, phi = 0) spaced as
//   s = centre + scale sinh(u),   u uniform in [u_min, u_max],  s spanning [-pi/2, pi/2],
// finest at the flat interfaces' exit direction, with scale a quarter of the lobe's estimated width
// (sigma (1 - 1/n) of the sharper interface, n its index ratio): 128 samples put ~9 within one lobe width there and
// are a few degrees apart at grazing. The samples are computed side by side on the machine's cores, and kept as their
// terms in the optical depth (UnscatteredLight::btdf_terms), so that a change of T alone re-weighs them.
// shaders/unscattered.glsl reads it with linear filtering; unscattered_plane_value() is the CPU twin.
#pragma once

#include <memory>
#include <vector>

#include "core/unscattered/unscattered_light.h"

namespace skinlayer {

struct UnscatteredPlane {
  double centre = 0.0;  // the flat interfaces' exit angle, signed [rad]
  double scale = 0.01;  // [rad], a quarter of the lobe's estimated width
  double u_min = -1.0;
  double u_max = 1.0;
  std::vector<float> btdf;  // [1/sr] at u_k = u_min + k (u_max - u_min) / (n - 1); empty when there is none
  UnscatteredLight light;   // what was sampled, and at which incident angle
  double theta_i = -1.0;
  // Per sample, the BTDF's terms in the optical depth (shared: a scene copies its plane).
  std::shared_ptr<const std::vector<std::vector<DepthTerm>>> terms;
};

// With `previous` sampling the same light at the same angle (an albedo or g change), that is returned unchanged; the
// same light at another optical depth (a T change) re-weighs previous's terms instead of sampling anew.
UnscatteredPlane sample_unscattered_plane(const UnscatteredLight& light, double theta_i, int samples = 128,
                                          const UnscatteredPlane* previous = nullptr);

// The signed exit angle of sample k (radians, clamped to [-pi/2, pi/2]).
double unscattered_plane_angle(const UnscatteredPlane& plane, std::size_t k);

// The texture's value at signed exit angle s: linear interpolation in u, as the GPU filters it.
double unscattered_plane_value(const UnscatteredPlane& plane, double signed_theta_o);

}  // namespace skinlayer
