#include "tests/bench/solve_stages.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "core/interfaces/interface_albedo.h"
#include "core/interfaces/interface_operators.h"

namespace skinlayer::bench {
namespace {

std::vector<double> negated(const std::vector<double>& values) {
  std::vector<double> result = values;
  for (double& v : result) v = -v;
  return result;
}

// The interface's accurate reflectance or transmittance for light from each cosine (z_sign: which side).
std::vector<double> fractions(const RoughDielectric& interface, const std::vector<double>& mu, double z_sign,
                              bool reflected) {
  std::vector<Vec3> toward_light;
  for (double c : mu) toward_light.emplace_back(std::sqrt(std::max(0.0, 1.0 - c * c)), 0.0, z_sign * std::abs(c));
  std::vector<double> result;
  for (const InterfaceAlbedo& a : interface_albedo(interface, toward_light)) {
    result.push_back(reflected ? a.reflectance : a.transmittance);
  }
  return result;
}

}  // namespace

Material ordinate_sweep_material() {
  Material material;
  material.sigma = 0.8;
  material.g = 0.5;
  return material;
}

StageInputs default_stage_inputs() {
  StageInputs in;
  // Stam's interfaces: the stages below build the single-scattering kernels only (RoughDielectric{eta, sigma}), so
  // they time the solve that has no multiply scattered lobe, and the report compares them with that solve.
  in.material.microfacet = MicrofacetModel::Single;
  in.resolution = choose_resolution(in.material);
  in.quadrature = double_gauss_half_range(in.resolution.ordinates);
  for (int i = 0; i < in.resolution.table_size; ++i) {
    in.grid_mu.push_back(std::max(1e-6, std::cos(LayerTables::grid_angle(i, in.resolution.table_size))));
  }
  in.modes = solve(in.material).modes();
  return in;
}

PhaseMatrices phase_stage(const StageInputs& in) {
  const CosineProjector projector(in.resolution.max_modes, in.resolution.phase_azimuths);
  return henyey_greenstein_matrices(in.material.g, in.quadrature.nodes, in.quadrature.weights, projector);
}

InterfaceStage interface_stage(const StageInputs& in) {
  const CosineProjector projector(in.resolution.interface_modes, in.resolution.interface_azimuths);
  const RoughDielectric top{in.material.eta, in.material.sigma};
  const std::vector<double>& up = in.quadrature.nodes;
  const std::vector<double> down = negated(up);
  InterfaceStage stage;
  stage.reflect_top = interface_fourier(top, up, down, projector);
  match_reflection_energy(stage.reflect_top, up, in.quadrature.weights, fractions(top, up, -1.0, true));
  apply_quadrature_weights(stage.reflect_top, up, in.quadrature.weights);
  stage.source_top = interface_fourier(top, negated(in.grid_mu), down, projector);
  match_column_energy(stage.source_top, up, in.quadrature.weights, fractions(top, in.grid_mu, 1.0, false));
  for (const Eigen::MatrixXd& mode : stage.source_top) {
    stage.exit_top.push_back(mode.transpose() / (in.material.eta * in.material.eta));
  }
  apply_quadrature_weights(stage.exit_top, up, in.quadrature.weights);
  return stage;
}

std::vector<SlabEigenSolution> eigen_stage(const StageInputs& in, const PhaseMatrices& phase) {
  std::vector<SlabEigenSolution> result;
  const double albedo = std::min(in.material.albedo, 1.0 - 1e-9);
  for (int m = 0; m < in.modes; ++m) {
    result.push_back(slab_eigen(in.quadrature.nodes, in.quadrature.weights, phase.same[m], phase.opposite[m],
                                albedo * fourier_azimuth_weight(m)));
  }
  return result;
}

double linear_solve_stage(const StageInputs& in, const InterfaceStage& interfaces,
                          const std::vector<SlabEigenSolution>& eigen) {
  double checksum = 0.0;
  for (int m = 0; m < in.modes; ++m) {
    BoundaryProblem problem;
    problem.eigen = &eigen[m];
    problem.tau = in.material.tau;
    problem.reflect_top = interfaces.reflect_top[m];
    problem.reflect_bottom = interfaces.reflect_top[m];  // the default's bottom mirrors its top
    problem.source_top = interfaces.source_top[m];
    const NodeField field = solve_boundary(problem, static_cast<int>(in.grid_mu.size()));
    const Eigen::MatrixXd reflection = interfaces.exit_top[m] * field.up_top;
    const Eigen::MatrixXd transmission = interfaces.exit_top[m] * field.down_bottom;
    checksum += reflection(0, 0) + transmission(0, 0);
  }
  return checksum;
}

LayerTables spline_stage(const LayerTables& tables) { return tables.refined(2); }

}  // namespace skinlayer::bench
