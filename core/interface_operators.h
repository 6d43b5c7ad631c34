// Discretized interface operators (Stam 2001's t12, R21, R23, ...): Fourier coefficients of a rough interface's
// BSDF between sets of propagation directions, and the radiance-to-radiance matrices built from them.
#pragma once

#include <span>

#include "core/fourier.h"
#include "core/microfacet.h"

namespace skinlayer {

// f^m(d_from -> d_to) of the interface's full BSDF (reflection or transmission, whichever the signs imply), for
// signed propagation cosines. Per mode an (n_to x n_from) matrix, in 1/sr.
FourierKernel interface_fourier(const RoughDielectric& interface, std::span<const double> mu_from,
                                std::span<const double> mu_to, const CosineProjector& projector);

// Turns coefficients over quadrature directions (from = nodes with weights a_j) into operators that map node
// radiance to outgoing radiance:  K^m(o, j) = c_m f^m(mu_j -> mu_o) |mu_j| a_j  (dimensionless).
void apply_quadrature_weights(FourierKernel& kernel, std::span<const double> nodes, std::span<const double> weights);

}  // namespace skinlayer
