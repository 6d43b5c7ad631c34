// Units and angle conventions used everywhere in skinlayer. This is the one place they are written down.
//
// Geometry
//   * The layer is plane-parallel. The macroscopic normal n = +z points from the layer up into the air above.
//   * Optical depth tau in [0, tau_b] increases downward; tau = 0 is the top interface.
//
// Directions, two conventions
//   * Graphics convention (every public function that takes theta/phi, and the command line):
//       - omega_i points toward the light and omega_o toward the viewer, both away from the surface.
//       - theta is measured from the normal of the side where the direction lies: the upper normal (+z) for the
//         incident direction and for reflection, the lower normal (-z) for transmission.
//       - phi = phi_o - phi_i. phi = pi is "forward": the mirror direction in reflection and the straight-through
//         direction in transmission. phi = 0 is back toward the light.
//   * Propagation convention (inside the solver only): radiance is labelled by the direction it travels,
//     d = (mu, phi_prop) with mu = d.z in [-1, 1]; mu > 0 travels up. A BSDF used with propagation labels is
//     f_prop(d_in -> d_out) = f(omega_i = -d_in, omega_o = d_out), and Delta phi_prop = phi - pi, so a Fourier
//     coefficient in propagation azimuth maps to the graphics one by cos(m Delta phi_prop) = (-1)^m cos(m phi).
//
// Fourier convention (full cosine series) for any kernel that depends on azimuth only through Delta phi:
//     K(Delta phi) = sum_{m >= 0} K^m cos(m Delta phi),
//     K^0 = (1/2pi) int_0^{2pi} K,   K^m = (1/pi) int_0^{2pi} K cos(m Delta phi)   (m >= 1),
//     int_0^{2pi} K(phi - phi') cos(m phi') dphi' = c_m K^m cos(m phi),   c_0 = 2 pi, c_m = pi (m >= 1).
//
// Units
//   * Angles: radians in core/, degrees on the command line and in the UI.
//   * BSDFs (BRDF, BTDF, phase functions) are in 1/sr and are NOT cosine-weighted unless a name says so
//     ("cosine_weighted", "projected"). A BTDF is a radiance BSDF: it includes the (n_t/n_i)^2 radiance scaling.
//   * Reflectance, transmittance and absorptance are dimensionless energy fractions of the incident flux on a
//     horizontal plane (directional-hemispherical).
#pragma once

#include <numbers>

namespace skinlayer {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInvPi = std::numbers::inv_pi;

inline constexpr double degrees_to_radians(double degrees) { return degrees * (kPi / 180.0); }
inline constexpr double radians_to_degrees(double radians) { return radians * (180.0 / kPi); }

// c_m of the Fourier convention above: the azimuthal integral of cos(m phi)^2 over [0, 2 pi).
inline constexpr double fourier_azimuth_weight(int m) { return m == 0 ? 2.0 * kPi : kPi; }

// (-1)^m: converts a coefficient in propagation azimuth to graphics azimuth and back.
inline constexpr double azimuth_parity(int m) { return (m % 2 == 0) ? 1.0 : -1.0; }

}  // namespace skinlayer
