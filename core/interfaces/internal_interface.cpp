#include "core/interfaces/internal_interface.h"

#include <algorithm>
#include <functional>
#include <optional>

#include "core/conventions.h"
#include "core/interfaces/interface_operators.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/interfaces/multiple_scattering.h"

namespace skinlayer {

std::size_t InternalInterfaceKernels::bytes() const {
  std::size_t total = 0;
  for (const FourierKernel* k : {&reflect_above, &reflect_below, &transmit_down, &transmit_up, &reflect_above_rows,
                                 &transmit_up_rows, &reflect_below_rows, &beam_reflect}) {
    total += fourier_kernel_bytes(*k);
  }
  for (const InterfaceKernel* k : {&transmit_down_rows, &beam_transmit, &beam_reflect_rows, &beam_transmit_rows}) {
    total += k->bytes();
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

  // The interface's multiply scattered lobe, built once for all of its kernels (none under MicrofacetModel::Single).
  const std::optional<MultipleScatteringLobe> multiple = multiple_scattering_lobe(interface, projector.modes());
  const MultipleScatteringLobe* lobe = multiple ? &*multiple : nullptr;

  // The slope-space albedos per node first: the reflections and the downward transmission are matched to them, each
  // part (single and multiple scattering) to its own (matched_interface_kernel).
  std::vector<InterfaceAlbedoParts> above, below;
  run_parallel(parallel_for, 2, [&](int side) {
    (side == 0 ? above : below) = interface_albedo_parts_along(interface, up, side == 0 ? 1.0 : -1.0, lobe);
  });
  k.from_above = totals(above);
  k.from_below = totals(below);
  // The downward transmission first: its multiply scattered part, matched from above, fixes by reciprocity what
  // that part carries up from below, E(j), and the reflection below keeps the rest of the multiply scattered light,
  // l - E(j), so that every node conserves exactly from both sides (the table's shares satisfy reciprocity only to
  // its noise, about 1% of l s).
  InterfaceKernel down_kernel = matched_interface_kernel(
      interface, down, down, projector, EnergyMatch::TransmittedColumns, above, up, weights, cancelled, lobe);
  if (down_kernel.has_multiple()) {
    const double c0 = fourier_azimuth_weight(0);
    const Eigen::MatrixXd& mode0 = down_kernel.multiple.front();
    for (Eigen::Index j = 0; j < mode0.rows(); ++j) {
      double carried = 0.0;  // sum_o c_0 a_o mu_o f_up(o <- j), f_up = f_down^T / eta^2
      for (Eigen::Index o = 0; o < mode0.cols(); ++o) {
        carried += c0 * weights[static_cast<std::size_t>(o)] * up[static_cast<std::size_t>(o)] * mode0(j, o) /
                   (interface.eta * interface.eta);
      }
      InterfaceAlbedo& rest = below[static_cast<std::size_t>(j)].multiple;
      const double total = rest.reflectance + rest.transmittance;
      rest = {std::max(0.0, total - carried), std::min(carried, total)};
    }
    k.from_below = totals(below);
  }
  k.transmit_down = std::move(down_kernel.kernel);
  k.transmit_up = transmission_by_reciprocity(k.transmit_down, interface.eta);
  apply_quadrature_weights(k.transmit_down, up, weights);
  apply_quadrature_weights(k.transmit_up, up, weights);
  std::vector<std::function<void()>> tasks;
  tasks.emplace_back([&] {
    k.reflect_above = matched_interface_kernel(interface, down, up, projector, EnergyMatch::Reflection, above, up,
                                               weights, cancelled, lobe)
                          .kernel;
    apply_quadrature_weights(k.reflect_above, up, weights);
  });
  tasks.emplace_back([&] {
    k.reflect_below = matched_interface_kernel(interface, up, down, projector, EnergyMatch::Reflection, below, up,
                                               weights, cancelled, lobe)
                          .kernel;
    apply_quadrature_weights(k.reflect_below, up, weights);
  });
  if (needs.up_rows) {
    tasks.emplace_back([&] {
      k.reflect_above_rows = matched_interface_kernel(interface, down, mu_out, projector, EnergyMatch::ReflectedRows,
                                                      above, {}, {}, cancelled, lobe)
                                 .kernel;
      apply_quadrature_weights(k.reflect_above_rows, up, weights);
      k.transmit_up_rows = matched_interface_kernel(interface, up, mu_out, projector, EnergyMatch::TransmittedRows,
                                                    below, {}, {}, cancelled, lobe)
                               .kernel;
      apply_quadrature_weights(k.transmit_up_rows, up, weights);
    });
  }
  if (needs.down_rows) {
    tasks.emplace_back([&] {
      k.reflect_below_rows = matched_interface_kernel(interface, up, down_out, projector, EnergyMatch::ReflectedRows,
                                                      below, {}, {}, cancelled, lobe)
                                 .kernel;
      apply_quadrature_weights(k.reflect_below_rows, up, weights);
      k.transmit_down_rows = matched_interface_kernel(interface, down, down_out, projector,
                                                      EnergyMatch::TransmittedRows, above, {}, {}, cancelled, lobe);
      apply_quadrature_weights(k.transmit_down_rows, up, weights);
    });
  }
  if (needs.beam) {
    tasks.emplace_back([&] {
      const std::vector<InterfaceAlbedoParts> beam = interface_albedo_parts_along(interface, mu_in, 1.0, lobe);
      k.beam_albedo = totals(beam);
      k.beam_reflect = matched_interface_kernel(interface, down_in, up, projector, EnergyMatch::ReflectedColumns, beam,
                                                up, weights, cancelled, lobe)
                           .kernel;
      k.beam_transmit = matched_interface_kernel(interface, down_in, down, projector, EnergyMatch::TransmittedColumns,
                                                 beam, up, weights, cancelled, lobe);
      if (needs.up_rows) {
        k.beam_reflect_rows = matched_interface_kernel(interface, down_in, mu_out, projector,
                                                       EnergyMatch::ReflectedRows, beam, {}, {}, cancelled, lobe);
      }
      if (needs.down_rows) {
        k.beam_transmit_rows = matched_interface_kernel(interface, down_in, down_out, projector,
                                                        EnergyMatch::TransmittedRows, beam, {}, {}, cancelled, lobe);
      }
    });
  }
  run_parallel(parallel_for, static_cast<int>(tasks.size()), [&](int i) { tasks[static_cast<std::size_t>(i)](); });
  return k;
}

}  // namespace skinlayer
