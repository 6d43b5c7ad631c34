// The phase-function half of a solve's albedo-independent work: the Henyey-Greenstein kernel projected between the
// ordinates, and between them and the outside directions where light is scattered straight to or from outside (an
// open top's beam, exits without a top interface). It depends on g, the ordinates, the projected modes and the
// outside directions, never on the albedo or the depth, so a SolveCache keeps it across Omega and T changes.
#pragma once

#include <span>
#include <vector>

#include "core/cancellation.h"
#include "core/medium/henyey_greenstein.h"
#include "core/series/fourier.h"
#include "core/series/quadrature.h"
#include "core/solve/boundary_solve.h"

namespace skinlayer {

struct PhaseKernels {
  PhaseMatrices phase;  // between the nodes, mode 0 renormalized (henyey_greenstein.h)
  // p^m from the open top's beam (-mu_in) to the nodes up and down, and to the exits up and down.
  FourierKernel beam_up_nodes, beam_down_nodes, beam_rows_up, beam_rows_down;
  // p^m from the nodes (up, down) to the exits, where light leaves without a top interface.
  FourierKernel same_rows, opposite_rows;

  std::size_t bytes() const;
};

// beam: the beam enters unscattered (open top); exterior: exits are scattered to directly (open top or open base).
// `cancelled` is asked once per direction of every kernel and between blocks of their projections.
PhaseKernels phase_kernels(double g, const QuadratureRule& quadrature, int max_modes, int phase_azimuths,
                           std::span<const double> mu_in, std::span<const double> mu_out, bool beam, bool exterior,
                           const CancelCheck& cancelled = {});

// The beam's particular solution (core/solve/boundary_solve.h) in a slab of single-scattering albedo `albedo` (<= the
// solver's clamp), Fourier mode m, for unit irradiance mu0 F = 1 along each mu_in (kernels built with beam = true).
// Mode 0's first-scattering source is scaled so that the quadrature scatters exactly the energy the beam loses:
// c_0 sum_j a_j (p^0(mu_j, -mu0) + p^0(-mu_j, -mu0)) = 1, as mode 0's phase matrix does between nodes.
BeamParticular beam_particular(const PhaseKernels& kernels, const QuadratureRule& quadrature, int m, double albedo,
                               std::span<const double> mu_in);

}  // namespace skinlayer
