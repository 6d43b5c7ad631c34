// The unscattered BTDF through two rough interfaces (UnscatteredPath::TopThenBottom,
// core/unscattered/unscattered_light.h) as a cosine series in azimuth, at every pair of polar angles of two lists at
// once: what a tabulated Fourier BSDF stores.
//
// unscattered_light.h evaluates the path at one direction pair by a slope-space quadrature (~90 us). Here the
// azimuthal convolution becomes a product per mode instead. In propagation labels (core/conventions.h), with T^m the
// top's transmission kernel from the incident direction to the internal direction of cosine mu' (travelling down)
// and B^m the bottom's from there to the exit,
//   f_T^m(o, i) = (-1)^m c_m int_0^1 B^m(o, mu') e^{-tau / mu'} T^m(mu', i) mu' dmu'          [1/sr]
// times the stack's outer attenuation e^{-tau_before / mu_i} e^{-tau_after / mu_o}; (-1)^m turns propagation
// azimuth into graphics azimuth, and c_m (2 pi, then pi) is the azimuthal integral of the cosine series'
// product. The mu' integral is a composite Gauss-Legendre rule in theta' whose panels are half as wide as the
// narrower interface's refraction lobe (microfacet.h's refracted_lobe_width), so it follows the lobes that the
// integrand is a product of.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/parallel_for.h"
#include "core/unscattered/unscattered_light.h"

namespace skinlayer {

// Modes enough for the two interfaces' lobes in azimuth: 24 / sigma_min, in [32, 512].
int two_interface_series_modes(const UnscatteredLight& light);

// One matrix per mode m < modes, (theta_o.size() x theta_i.size()), graphics convention (core/conventions.h):
// f_T(theta_i, theta_o, phi) = sum_m result[m](o, i) cos(m phi), the light's btdf() for a TopThenBottom path.
// Angles in radians, theta_o from the lower normal. Throws std::invalid_argument for another path.
std::vector<Eigen::MatrixXd> two_interface_btdf_series(const UnscatteredLight& light, std::span<const double> theta_i,
                                                       std::span<const double> theta_o, int modes,
                                                       const ParallelFor& parallel_for = {});

}  // namespace skinlayer
