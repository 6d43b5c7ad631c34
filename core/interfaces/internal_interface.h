// A rough dielectric interface between two stacked layers (core/material.h, StackedLayer::interface), discretized on
// the ordinates both layers share: its node operators per Fourier mode, and the rows and beam columns a stack under
// an open top or over an open base needs. Frame +z up; the layer above has index n_a, the one below n_b, and the
// interface's RoughDielectric has eta = n_b / n_a (core/interfaces/microfacet.h). Propagation convention
// (core/conventions.h), before the per-mode parity, as the layer's own interface kernels
// (core/interfaces/layer_interfaces.h).
//
// The face condition it enters (core/solve/stack_boundary.h), for node radiances u+- just above (a) and below (b):
//   u+_a = R_a u-_a + T_up u+_b,    u-_b = R_b u+_b + T_down u-_a.
// R_a and R_b are matched to the interface's slope-space reflectances per node from above and below
// (match_reflection_energy, reciprocal), T_down to its transmittances from above (match_column_energy), and T_up is
// T_down's reciprocal (transpose / eta^2), as the layer's exits inherit from its sources.
#pragma once

#include <span>
#include <vector>

#include "core/cancellation.h"
#include "core/interfaces/interface_albedo.h"
#include "core/interfaces/interface_operators.h"
#include "core/interfaces/microfacet.h"
#include "core/parallel_for.h"
#include "core/series/fourier.h"
#include "core/series/quadrature.h"

namespace skinlayer {

struct InternalInterfaceKernels {
  RoughDielectric interface;
  // Node operators (quadrature weights applied): down-above -> up-above, up-below -> down-below, down-above ->
  // down-below, up-below -> up-above.
  FourierKernel reflect_above, reflect_below, transmit_down, transmit_up;
  // Per node, the interface's albedos for light arriving from above (travelling down) and from below.
  std::vector<InterfaceAlbedo> from_above, from_below;
  // To the upward exits mu_out (weights applied): from the down nodes above (reflection) and from the up nodes
  // below (transmission). Empty unless asked for.
  FourierKernel reflect_above_rows, transmit_up_rows;
  // To the downward exits -mu_out: from the up nodes below (reflection) and the down nodes above (transmission).
  FourierKernel reflect_below_rows;
  InterfaceKernel transmit_down_rows;  // its multiply scattered part apart, as the beam's below
  // A collimated beam travelling down along -mu_in (irradiance mu_in F = 1 on the interface), reflected into the up
  // nodes above and transmitted into the down nodes below (columns energy-matched, no weights), and to the exits.
  // The InterfaceKernel ones are those that the exact unscattered light replaces in part: their multiply scattered
  // part of mode 0 stays apart (0 x 0 under MicrofacetModel::Single).
  FourierKernel beam_reflect;
  InterfaceKernel beam_transmit, beam_reflect_rows, beam_transmit_rows;
  // Per incident direction, the interface's albedos for the beam.
  std::vector<InterfaceAlbedo> beam_albedo;

  std::size_t bytes() const;
};

struct InternalInterfaceNeeds {
  bool up_rows = false;    // exits up through the layer above (an open top)
  bool down_rows = false;  // exits down through the layer below (an open base)
  bool beam = false;       // the open top's beam reaches the interface unscattered
};

InternalInterfaceKernels internal_interface_kernels(const RoughDielectric& interface, const QuadratureRule& quadrature,
                                                    int max_modes, int interface_azimuths,
                                                    std::span<const double> mu_in, std::span<const double> mu_out,
                                                    const InternalInterfaceNeeds& needs,
                                                    const ParallelFor& parallel_for = {},
                                                    const CancelCheck& cancelled = {});

}  // namespace skinlayer
