// The response of a layer to light at one lateral spatial frequency: the first step from the BSDF, which integrates
// over the whole surface, to the spatially resolved response (docs/model.md §21).
//
// A pencil beam of unit power enters at the origin of the top face. Transformed in the lateral coordinates,
// I(k) = int I(x) e^{-i k.x} d^2x, the transport equation for each spatial frequency k (along x) reads, in optical
// depth tau (downward) and mean free paths:
//   mu dI/dtau + (1 + i k sin(theta) cos(phi)) I = Omega int p I' d omega' + Omega p(mu) e^{-tau},
// where mu = cos(theta) is signed (mu > 0 travels down) and the last term is the first scattering of the beam.
// R(k) and T(k), the scattered light leaving the top and the bottom per unit incident power, are the Hankel
// transforms of the profiles: R(k) = int_0^inf R(r) J0(k r) 2 pi r dr, so R(0) is the subsurface reflectance.
//
// Below the layer: an index-matched half-space or none. Above it: no interface (eta = 1, the open layer) or a rough
// one (lateral_top_interface.h), through the BSDF's own operators. Normal incidence.
#pragma once

#include <Eigen/Core>

#include "core/medium/henyey_greenstein.h"
#include "core/series/quadrature.h"

namespace skinlayer {

struct LateralTopInterface;

struct LateralFrequencyResolution {
  int ordinates = 16;      // double-Gauss nodes per hemisphere
  int azimuth_modes = 24;  // cosine modes m = 0 .. azimuth_modes - 1 that the k.s term couples
};

// The phase function's Fourier matrices on the nodes, as every lateral solve projects them (mode 0 renormalized to
// conserve energy on the nodes, §7).
PhaseMatrices lateral_phase_matrices(double g, const QuadratureRule& quadrature, int modes);

// C, the k.s term between the modes (§21.2): with I = sum_m i^m a_m cos(m phi), the streaming operator of node mu is
// (1 + k sin(theta) C) / mu on the coefficients a_m, C(m, m - 1) = 1 for m = 1 and 1/2 above, C(m, m + 1) = -1/2.
Eigen::MatrixXd lateral_mode_coupling(int modes);

struct LateralFrequencyResponse {
  double reflectance = 0.0;    // R(k): scattered light out of the top, per unit incident power
  double transmittance = 0.0;  // T(k): scattered light out of the bottom (the direct beam, a delta at r = 0, is not
                               // in it); 0 for a semi-infinite layer
};

// tau: optical depth (+infinity: semi-infinite); albedo Omega in [0, 1); g the Henyey-Greenstein asymmetry;
// k >= 0 in 1 / mean free path. Throws std::invalid_argument for values outside those ranges (Omega = 1 with
// k = 0 in a semi-infinite layer has no decaying solution).
LateralFrequencyResponse open_layer_lateral_response(double tau, double albedo, double g, double k,
                                                     const LateralFrequencyResolution& resolution = {});

// The same under a rough top, whose operators were built for `resolution` (lateral_top_interface). The beam enters
// as the top's refracted node radiance, so the transmittance holds all the light leaving the bottom, the part that
// crossed unscattered included.
LateralFrequencyResponse rough_top_lateral_response(double tau, double albedo, double g, const LateralTopInterface& top,
                                                    double k, const LateralFrequencyResolution& resolution = {});

// The open layer's first order in the albedo: the beam scattered once, then only streaming (the operator
// without scattering). Its k-coupling joins the modes of one node alone, so it costs N small eigen-solves.
LateralFrequencyResponse open_layer_single_scattering_response(double tau, double albedo, double g, double k,
                                                               const LateralFrequencyResolution& resolution = {});

}  // namespace skinlayer
