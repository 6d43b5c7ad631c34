#include "core/medium/layer_phase.h"

#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"

namespace skinlayer {

std::size_t PhaseKernels::bytes() const {
  std::size_t total = 0;
  for (const FourierKernel* kernel : {&phase.same, &phase.opposite, &beam_up_nodes, &beam_down_nodes, &beam_rows_up,
                                      &beam_rows_down, &same_rows, &opposite_rows}) {
    total += fourier_kernel_bytes(*kernel);
  }
  return total;
}

PhaseKernels phase_kernels(double g, const QuadratureRule& quadrature, int max_modes, int phase_azimuths,
                           std::span<const double> mu_in, std::span<const double> mu_out, bool beam, bool exterior,
                           const CancelCheck& cancelled) {
  PhaseKernels k;
  const CosineProjector projector(max_modes, phase_azimuths);
  const std::span<const double> up = quadrature.nodes;
  const std::vector<double> down = negated(up);
  const std::vector<double> down_in = negated(mu_in);
  const std::vector<double> down_out = negated(mu_out);
  k.phase = henyey_greenstein_matrices(g, up, quadrature.weights, projector, cancelled);
  if (beam) {
    k.beam_up_nodes = henyey_greenstein_fourier(g, down_in, up, projector, cancelled);
    k.beam_down_nodes = henyey_greenstein_fourier(g, down_in, down, projector, cancelled);
    if (exterior) {
      k.beam_rows_up = henyey_greenstein_fourier(g, down_in, mu_out, projector, cancelled);
      k.beam_rows_down = henyey_greenstein_fourier(g, down_in, down_out, projector, cancelled);
    }
  }
  if (exterior) {
    k.same_rows = henyey_greenstein_fourier(g, up, mu_out, projector, cancelled);
    k.opposite_rows = henyey_greenstein_fourier(g, down, mu_out, projector, cancelled);
  }
  return k;
}

BeamParticular beam_particular(const PhaseKernels& kernels, const QuadratureRule& quadrature, int m, double albedo,
                               std::span<const double> mu_in) {
  const Eigen::Index n = quadrature.size();
  const Eigen::Map<const Eigen::VectorXd> mu0(mu_in.data(), static_cast<Eigen::Index>(mu_in.size()));
  const Eigen::VectorXd flux = mu0.cwiseInverse();  // F = 1/mu0
  Eigen::MatrixXd source_up = albedo * kernels.beam_up_nodes[m] * flux.asDiagonal();
  Eigen::MatrixXd source_down = albedo * kernels.beam_down_nodes[m] * flux.asDiagonal();
  if (m == 0) {
    const Eigen::Map<const Eigen::VectorXd> a(quadrature.weights.data(), n);
    for (Eigen::Index k = 0; k < mu0.size(); ++k) {
      const double scattered =
          fourier_azimuth_weight(0) * a.dot(kernels.beam_up_nodes[0].col(k) + kernels.beam_down_nodes[0].col(k));
      source_up.col(k) /= scattered;
      source_down.col(k) /= scattered;
    }
  }
  return beam_particular_solution(quadrature.nodes, quadrature.weights, kernels.phase.same[m],
                                  kernels.phase.opposite[m], albedo * fourier_azimuth_weight(m), source_up, source_down,
                                  mu_in);
}

}  // namespace skinlayer
