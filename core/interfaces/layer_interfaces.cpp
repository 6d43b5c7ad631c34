#include "core/interfaces/layer_interfaces.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "core/interfaces/interface_operators.h"
#include "core/interfaces/multiple_scattering.h"

namespace skinlayer {

std::vector<double> negated(std::span<const double> cosines) {
  std::vector<double> result(cosines.begin(), cosines.end());
  for (double& v : result) v = -v;
  return result;
}

RoughDielectric top_interface(const Material& material) { return {material.eta, material.sigma, material.microfacet}; }

RoughDielectric bottom_interface(const Material& material) {
  return {1.0 / material.bottom_eta(), material.bottom_sigma(), material.microfacet};
}

LayerGeometry classify_layer(const Material& material) {
  LayerGeometry geometry;
  geometry.top_open = material.eta == 1.0;
  geometry.top = top_interface(material);
  switch (material.bottom.kind) {
    case BottomKind::Air:
      geometry.base = material.bottom_eta() == 1.0 ? LayerBase::Open : LayerBase::Rough;
      break;
    case BottomKind::Matched:
      geometry.base = LayerBase::Open;
      break;
    case BottomKind::Lambert:
      geometry.base = LayerBase::Lambert;
      break;
  }
  if (geometry.base == LayerBase::Rough) {
    geometry.bottom = bottom_interface(material);
  }
  geometry.bottom_mirrors_top = geometry.base == LayerBase::Rough && material.bottom_eta() == material.eta &&
                                material.bottom_sigma() == material.sigma;
  return geometry;
}

Eigen::MatrixXd lambert_reflection(const QuadratureRule& quadrature, double albedo) {
  const Eigen::Index n = quadrature.size();
  Eigen::RowVectorXd row(n);
  for (Eigen::Index j = 0; j < n; ++j) row(j) = 2.0 * albedo * quadrature.nodes[j] * quadrature.weights[j];
  return row.replicate(n, 1);
}

std::size_t InterfaceKernels::bytes() const {
  std::size_t total = fourier_kernel_bytes(r_surface_multiple);
  for (const FourierKernel* k : {&r_top, &r_top_rows, &r_bottom, &s_bottom_beam, &r_bottom_rows}) {
    total += fourier_kernel_bytes(*k);
  }
  for (const InterfaceKernel* k :
       {&t_source, &t_exit, &t_source_exterior, &t_bottom_exit, &t_bottom_beam, &r_bottom_beam_rows}) {
    total += k->bytes();
  }
  return total + sizeof(InterfaceAlbedo) * (top_inside.size() + bottom_inside.size() + bottom_beam_albedo.size()) +
         sizeof(InterfaceAlbedoParts) * top_outside.size();
}

InterfaceKernels interface_kernels(const LayerGeometry& geometry, int ordinates, int max_modes, int interface_azimuths,
                                   std::span<const double> mu_in, std::span<const double> mu_out,
                                   const ParallelFor& parallel_for, KernelSet set, const CancelCheck& cancelled) {
  InterfaceKernels k;
  k.geometry = geometry;
  k.quadrature = double_gauss_half_range(ordinates);
  k.mu_in.assign(mu_in.begin(), mu_in.end());
  k.mu_out.assign(mu_out.begin(), mu_out.end());
  const std::size_t n = k.quadrature.nodes.size();
  k.top_inside.assign(n, InterfaceAlbedo{0.0, 1.0});
  k.bottom_inside.assign(n, InterfaceAlbedo{0.0, 1.0});
  const bool want_exit = !mu_out.empty();
  const CosineProjector surface(max_modes, interface_azimuths);
  const std::span<const double> up = k.quadrature.nodes;
  const std::span<const double> weights = k.quadrature.weights;
  const std::vector<double> down = negated(up);
  const std::vector<double> down_in = negated(mu_in);
  const std::vector<double> down_out = negated(mu_out);
  const bool rough_bottom = geometry.base == LayerBase::Rough;
  const bool bottom_is_top = rough_bottom && geometry.bottom_mirrors_top && !geometry.top_open;
  const bool all = set != KernelSet::BottomBounce;
  const bool surface_multiple_rows = set == KernelSet::All;

  // Each rough interface's multiply scattered lobe, built once for all of its kernels and albedos (none under
  // MicrofacetModel::Single).
  const auto shared_lobe = [&](const RoughDielectric& interface) -> std::shared_ptr<const MultipleScatteringLobe> {
    if (!has_multiple_scattering(interface)) return nullptr;
    return std::make_shared<const MultipleScatteringLobe>(interface, surface.modes());
  };
  if (!geometry.top_open) k.top_multiple = shared_lobe(geometry.top);
  if (rough_bottom && !bottom_is_top) k.bottom_multiple = shared_lobe(geometry.bottom);
  const MultipleScatteringLobe* top_lobe = k.top_multiple.get();
  const MultipleScatteringLobe* bottom_lobe = k.bottom_multiple.get();

  // Independent kernels, each written by one task: they run side by side on the caller's parallel-for. Each part of a
  // kernel (single and multiple scattering) is energy-matched to its own share of the accurate albedos
  // (matched_interface_kernel).
  std::vector<std::function<void()>> tasks;
  // The albedo parts the rows to outside directions are matched to after the tasks (match_multiple_rows), and those
  // rows with their multiply scattered parts apart until then.
  std::vector<InterfaceAlbedoParts> top_inside_parts, bottom_inside_parts, bottom_beam_parts;
  InterfaceKernel top_rows, bottom_rows, surface_multiple;
  if (!geometry.top_open && (all || bottom_is_top)) {
    tasks.emplace_back([&] {
      const std::vector<InterfaceAlbedoParts>& inside = top_inside_parts =
          interface_albedo_parts_along(geometry.top, up, -1.0, top_lobe);
      k.top_inside = totals(inside);
      k.r_top = matched_interface_kernel(geometry.top, up, down, surface, EnergyMatch::Reflection, inside, up, weights,
                                         cancelled, top_lobe)
                    .kernel;
      apply_quadrature_weights(k.r_top, up, weights);
    });
  }
  if (geometry.top_open) {
    k.top_outside =
        interface_albedo_parts_along(geometry.top, mu_in, 1.0, top_lobe);  // no interface: R = 0, T = 1, at once
  } else {
    tasks.emplace_back([&] {
      k.top_outside = interface_albedo_parts_along(geometry.top, mu_in, 1.0, top_lobe);
      k.t_source = matched_interface_kernel(geometry.top, down_in, down, surface, EnergyMatch::TransmittedColumns,
                                            k.top_outside, up, weights, cancelled, top_lobe);
      if (want_exit) {
        // By reciprocity the exit operator inherits the energy matching of the source columns, row by row.
        k.t_exit = transmission_by_reciprocity(k.t_source, geometry.top.eta);
        apply_quadrature_weights(k.t_exit, up, weights);
      }
    });
    if (all && want_exit && geometry.base == LayerBase::Open) {
      tasks.emplace_back([&] {
        k.t_source_exterior = interface_kernel(geometry.top, down_in, down_out, surface, cancelled, top_lobe);
        top_rows = interface_kernel(geometry.top, up, down_out, surface, cancelled, top_lobe);
        apply_quadrature_weights(top_rows, up, weights);
      });
    }
    if (surface_multiple_rows && want_exit && top_lobe != nullptr) {
      tasks.emplace_back([&] {
        surface_multiple.multiple = multiple_scattering_fourier(*top_lobe, down_in, mu_out);
        surface_multiple.kernel = surface_multiple.multiple;
      });
    }
  }
  if (rough_bottom && !bottom_is_top) {
    tasks.emplace_back([&] {
      const std::vector<InterfaceAlbedoParts>& inside = bottom_inside_parts =
          interface_albedo_parts_along(geometry.bottom, up, 1.0, bottom_lobe);
      k.bottom_inside = totals(inside);
      k.r_bottom = matched_interface_kernel(geometry.bottom, down, up, surface, EnergyMatch::Reflection, inside, up,
                                            weights, cancelled, bottom_lobe)
                       .kernel;
      apply_quadrature_weights(k.r_bottom, up, weights);
    });
    if (all && want_exit) {
      tasks.emplace_back([&] {
        // As for the top: the exit rows are the transposed source columns from the air below (propagating up), each
        // matched to its slope-space transmittance. A sharp, low-contrast bottom (sigma3 0.2, eta3 1.2) has an
        // interior lobe ~ sigma3 (1 - 1/eta3) wide, narrower than the node spacing: its unmatched node sums ripple
        // by percents across exit angles.
        const InterfaceKernel from_below =
            matched_interface_kernel(geometry.bottom, mu_out, up, surface, EnergyMatch::TransmittedColumns,
                                     interface_albedo_parts_along(geometry.bottom, mu_out, -1.0, bottom_lobe), up,
                                     weights, cancelled, bottom_lobe);
        k.t_bottom_exit = transmission_by_reciprocity(from_below, 1.0 / geometry.bottom.eta);
        apply_quadrature_weights(k.t_bottom_exit, up, weights);
      });
    }
  }
  if (all && rough_bottom && geometry.top_open) {
    tasks.emplace_back([&] {
      const std::vector<InterfaceAlbedoParts>& beam = bottom_beam_parts =
          interface_albedo_parts_along(geometry.bottom, mu_in, 1.0, bottom_lobe);
      k.bottom_beam_albedo = totals(beam);
      k.s_bottom_beam = matched_interface_kernel(geometry.bottom, down_in, up, surface, EnergyMatch::ReflectedColumns,
                                                 beam, up, weights, cancelled, bottom_lobe)
                            .kernel;
    });
    if (want_exit) {
      tasks.emplace_back([&] {
        k.t_bottom_beam = interface_kernel(geometry.bottom, down_in, down_out, surface, cancelled, bottom_lobe);
        bottom_rows = interface_kernel(geometry.bottom, down, mu_out, surface, cancelled, bottom_lobe);
        apply_quadrature_weights(bottom_rows, up, weights);
        k.r_bottom_beam_rows = interface_kernel(geometry.bottom, down_in, mu_out, surface, cancelled, bottom_lobe);
      });
    }
  }
  run_parallel(parallel_for, static_cast<int>(tasks.size()), [&](int i) { tasks[static_cast<std::size_t>(i)](); });
  // The rows to outside directions are no quadrature: their multiply scattered parts carry, column by column, what
  // the albedos give them (the top's reflection from outside symmetrically, to stay reciprocal).
  if (top_lobe != nullptr) {
    if (surface_multiple_rows) match_multiple_rows(surface_multiple, *top_lobe, down_in, true, k.top_outside, true);
    match_multiple_rows(k.t_source_exterior, *top_lobe, down_in, false, k.top_outside);
    match_multiple_rows(top_rows, *top_lobe, up, true, top_inside_parts);
  }
  if (bottom_lobe != nullptr) {
    match_multiple_rows(k.t_bottom_beam, *bottom_lobe, down_in, false, bottom_beam_parts);
    match_multiple_rows(bottom_rows, *bottom_lobe, down, true, bottom_inside_parts);
    match_multiple_rows(k.r_bottom_beam_rows, *bottom_lobe, down_in, true, bottom_beam_parts);
  }
  k.r_surface_multiple = std::move(surface_multiple.multiple);
  k.r_top_rows = std::move(top_rows.kernel);
  k.r_bottom_rows = std::move(bottom_rows.kernel);
  if (bottom_is_top) {
    k.r_bottom = k.r_top;
    if (all) k.t_bottom_exit = k.t_exit;
    k.bottom_inside = k.top_inside;
  }
  return k;
}

}  // namespace skinlayer
