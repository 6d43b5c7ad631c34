#include "core/interfaces/internal_interface.h"

#include <functional>

#include "core/interfaces/interface_operators.h"
#include "core/interfaces/layer_interfaces.h"

namespace skinlayer {

std::size_t InternalInterfaceKernels::bytes() const {
  std::size_t total = 0;
  for (const FourierKernel* k : {&reflect_above, &reflect_below, &transmit_down, &transmit_up, &reflect_above_rows,
                                 &transmit_up_rows, &reflect_below_rows, &transmit_down_rows, &beam_reflect,
                                 &beam_transmit, &beam_reflect_rows, &beam_transmit_rows}) {
    total += fourier_kernel_bytes(*k);
  }
  return total + sizeof(InterfaceAlbedo) * (from_above.size() + from_below.size() + beam_albedo.size());
}

InternalInterfaceKernels internal_interface_kernels(const RoughDielectric& interface, const QuadratureRule& quadrature,
                                                    int max_modes, int interface_azimuths,
                                                    std::span<const double> mu_in, std::span<const double> mu_out,
                                                    const InternalInterfaceNeeds& needs,
                                                    const ParallelFor& parallel_for, const CancelCheck& cancelled) {
  InternalInterfaceKernels k;
  k.interface = interface;
  const CosineProjector projector(max_modes, interface_azimuths);
  const std::span<const double> up = quadrature.nodes;
  const std::span<const double> weights = quadrature.weights;
  const std::vector<double> down = negated(up);
  const std::vector<double> down_in = negated(mu_in);
  const std::vector<double> down_out = negated(mu_out);

  // The slope-space albedos per node first: the reflections and the downward transmission are matched to them.
  run_parallel(parallel_for, 2, [&](int side) {
    (side == 0 ? k.from_above : k.from_below) = interface_albedos_along(interface, up, side == 0 ? 1.0 : -1.0);
  });
  std::vector<std::function<void()>> tasks;
  tasks.emplace_back([&] {
    k.reflect_above = interface_fourier(interface, down, up, projector, cancelled);
    match_reflection_energy(k.reflect_above, up, weights, reflectances(k.from_above));
    apply_quadrature_weights(k.reflect_above, up, weights);
  });
  tasks.emplace_back([&] {
    k.reflect_below = interface_fourier(interface, up, down, projector, cancelled);
    match_reflection_energy(k.reflect_below, up, weights, reflectances(k.from_below));
    apply_quadrature_weights(k.reflect_below, up, weights);
  });
  tasks.emplace_back([&] {
    k.transmit_down = interface_fourier(interface, down, down, projector, cancelled);
    match_column_energy(k.transmit_down, up, weights, transmittances(k.from_above));
    k.transmit_up = transmission_by_reciprocity(k.transmit_down, interface.eta);
    apply_quadrature_weights(k.transmit_down, up, weights);
    apply_quadrature_weights(k.transmit_up, up, weights);
  });
  if (needs.up_rows) {
    tasks.emplace_back([&] {
      k.reflect_above_rows = interface_fourier(interface, down, mu_out, projector, cancelled);
      apply_quadrature_weights(k.reflect_above_rows, up, weights);
      k.transmit_up_rows = interface_fourier(interface, up, mu_out, projector, cancelled);
      apply_quadrature_weights(k.transmit_up_rows, up, weights);
    });
  }
  if (needs.down_rows) {
    tasks.emplace_back([&] {
      k.reflect_below_rows = interface_fourier(interface, up, down_out, projector, cancelled);
      apply_quadrature_weights(k.reflect_below_rows, up, weights);
      k.transmit_down_rows = interface_fourier(interface, down, down_out, projector, cancelled);
      apply_quadrature_weights(k.transmit_down_rows, up, weights);
    });
  }
  if (needs.beam) {
    tasks.emplace_back([&] {
      k.beam_albedo = interface_albedos_along(interface, mu_in, 1.0);
      k.beam_reflect = interface_fourier(interface, down_in, up, projector, cancelled);
      match_column_energy(k.beam_reflect, up, weights, reflectances(k.beam_albedo));
      k.beam_transmit = interface_fourier(interface, down_in, down, projector, cancelled);
      match_column_energy(k.beam_transmit, up, weights, transmittances(k.beam_albedo));
      if (needs.up_rows) k.beam_reflect_rows = interface_fourier(interface, down_in, mu_out, projector, cancelled);
      if (needs.down_rows) k.beam_transmit_rows = interface_fourier(interface, down_in, down_out, projector, cancelled);
    });
  }
  run_parallel(parallel_for, static_cast<int>(tasks.size()), [&](int i) { tasks[static_cast<std::size_t>(i)](); });
  return k;
}

}  // namespace skinlayer
