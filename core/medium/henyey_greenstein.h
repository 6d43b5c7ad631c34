// The Henyey-Greenstein phase function and its Fourier/discrete-ordinate form.
#pragma once

#include <span>

#include "core/cancellation.h"
#include "core/series/fourier.h"

namespace skinlayer {

// p(cos Theta) = (1/4pi) (1 - g^2) / (1 + g^2 - 2 g cos Theta)^{3/2}, with int_{4pi} p d omega = 1.  [1/sr]
// Theta is the angle between the directions of propagation before and after scattering.
double henyey_greenstein(double cos_theta, double g);

// p^m(mu_to, mu_from) for signed propagation cosines: the full-cosine Fourier coefficients in Delta phi of
// p(mu mu' + sqrt(1-mu^2) sqrt(1-mu'^2) cos Delta phi), numerically projected (no Legendre truncation).
// `cancelled` is asked once per incident direction (project_propagation_kernel).
FourierKernel henyey_greenstein_fourier(double g, std::span<const double> mu_from, std::span<const double> mu_to,
                                        const CosineProjector& projector, const CancelCheck& cancelled = {});

// Discrete-ordinate phase matrices on the double-Gauss nodes mu_j > 0 with weights a_j (sum 1):
//   same[m](i, j) = p^m(mu_i, mu_j) = p^m(-mu_i, -mu_j),   opposite[m](i, j) = p^m(mu_i, -mu_j).
// Mode 0 is renormalized so that scattering conserves energy exactly on the quadrature:
//   c_0 sum_j (same + opposite)(i, j) a_j = 1 for every i,
// by correcting the forward (diagonal) entry of `same`, which keeps both matrices symmetric.
struct PhaseMatrices {
  FourierKernel same;
  FourierKernel opposite;
};
// `cancelled` is asked once per node and between blocks of the projection (core/cancellation.h).
PhaseMatrices henyey_greenstein_matrices(double g, std::span<const double> nodes, std::span<const double> weights,
                                         const CosineProjector& projector, const CancelCheck& cancelled = {});

}  // namespace skinlayer
