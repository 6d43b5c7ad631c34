// The tables of what a rough dielectric interface scatters more than once on its microsurface,
// core/data/microfacet_multiple_scattering.csv and core/data/microfacet_single_scattering_loss.csv (generator
// tests/generators/microfacet_multiple_scattering.cpp, from the microsurface random walk's next-event estimates,
// core/reference/multiple_scattering_estimate.h), and their interpolation to one interface.
//
// For each Beckmann sigma and index E = n_below / n_above > 1 of the grids, the lobe has three kernels of the
// multiply scattered BSDF (1/sr, not cosine-weighted): 0 the reflection from above, 1 the reflection from below, 2 the
// transmission from above to below. Each is sampled at polar angles theta_i, theta_o = 0, 5, ..., 90 degrees (cosines
// from the normal on each direction's own side) and at the azimuths of the table's header, phi = phi_o - phi_i in
// graphics convention (core/conventions.h; 180 degrees is forward), closest at the forward plane where the lobe is
// sharp; between them the lobe is exponential in phi (core/series/log_linear_azimuth_series.h). The loss table holds,
// at the same angles, the light single scattering leaves from above and from below, l(mu) (core's slope integrals),
// which is what the lobe carries.
//
// The lobe table holds each kernel's shape, f(i, o) / sqrt(l(i) l(o)) (l from the kernel's incident side at i and
// from its exit side at o), which varies with sigma and E far less than f itself: at normal incidence l grows
// five-hundredfold from sigma 0.3 to 0.5. A row holds one kernel and pair of polar angles, as a unit and whole
// numbers of it; reflection rows hold theta_o >= theta_i only (the kernels are reciprocal: the other half is the
// mirror), and a row of zeros is left out.
#pragma once

#include <Eigen/Core>
#include <array>
#include <span>
#include <vector>

namespace skinlayer {

struct MultipleScatteringSamples {
  static constexpr int kAngles = 19;         // polar angles 0, 5, ..., 90 degrees
  static constexpr double kAngleStep = 5.0;  // degrees
  std::vector<double> azimuths;              // radians, ascending from 0 to pi
  // [kernel] of (kAngles^2 x azimuths): row theta_i * kAngles + theta_o (grid indices), 1/sr.
  std::array<Eigen::MatrixXd, 3> kernels;
};

// The lobe between the grid's polar angles: the Catmull-Rom weights of the polar angle of |cosine| on them, the end
// values held beyond the grid (kAngles weights, at most four of them nonzero).
std::array<double, MultipleScatteringSamples::kAngles> polar_grid_weights(double cosine);
// The same weights as four (grid index, weight) terms, indices clamped to the grid (an end index may repeat).
struct PolarStencil {
  std::array<int, 4> index;
  std::array<double, 4> weight;
};
PolarStencil polar_grid_stencil(double cosine);

// The hemisphere integral of that interpolant of a function of the exit angle: int f |cos theta| d omega =
// sum_k q_k f(theta_k), for a function uniform in azimuth (2 pi int f(theta) cos theta sin theta d theta, each cell
// by 8-point Gauss-Legendre, which is exact for the cubic times cos sin to 1e-12).
const std::array<double, MultipleScatteringSamples::kAngles>& polar_grid_quadrature();

// The losses at the grid angles for light from above and from below, and the lobe's shapes, at Beckmann sigma and
// index E >= 1, interpolated by four-point (cubic Lagrange) weights in ln sigma, where the lobes' widths follow sigma,
// and in 1/E, the sine of the critical angle inside, where the light from below starts to be totally reflected
// (the losses in ln l); both clamped to the tables' grids (E below the grid's least takes its shape).
struct MultipleScatteringShape {
  MultipleScatteringSamples shapes;  // f(i, o) / sqrt(l(i) l(o))
  std::array<double, MultipleScatteringSamples::kAngles> loss_above{}, loss_below{};
};
MultipleScatteringShape multiple_scattering_shape(double sigma, double index);

}  // namespace skinlayer
