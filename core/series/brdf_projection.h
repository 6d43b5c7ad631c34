// Any BRDF as the solver's tables (core/series/layer_tables.h): its Fourier coefficients in azimuth on the tables'
// polar grid, so that whatever reads tables (the previewer's textures, its A/B comparison) shows it. With phi_j =
// 2 pi j / N, j < N (N = 4 M), the trapezoid rule, exact for trigonometric polynomials below degree N,
//   S_0(theta_i, theta_o) = (1/N) sum_j f(theta_i, theta_o, phi_j),
//   S_m(theta_i, theta_o) = (2/N) sum_j f(theta_i, theta_o, phi_j) cos(m phi_j),   0 < m < M   [1/sr],
// in core/conventions.h's graphics convention (phi = pi is the mirror direction). A lobe narrower than the grid or
// than M modes resolve is smoothed, as the solver's own tables smooth it. Reflection only: the transmission is 0,
// and there is no unscattered light.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>

#include "core/parallel_for.h"
#include "core/series/layer_tables.h"

namespace skinlayer {

// f(theta_i, theta_o, phi) per RGB channel, 1/sr, angles in radians.
using RgbBrdf = std::function<Eigen::Array3d(double theta_i, double theta_o, double phi)>;

// One LayerTables per channel, on grid_size polar angles (>= 4) and `modes` cosine terms (>= 1); the rows of
// theta_i run through parallel_for.
std::array<LayerTables, 3> project_brdf(const RgbBrdf& brdf, int grid_size, int modes, const ParallelFor& parallel_for);

}  // namespace skinlayer
