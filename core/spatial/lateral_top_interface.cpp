// docs/model.md §21.9 and §21.12: the BSDF solve's top operators, for light at normal incidence or diffuse, and no
// exit directions.
#include "core/spatial/lateral_top_interface.h"

#include <stdexcept>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"

namespace skinlayer {

QuadratureRule diffuse_incidence_cosines() {
  QuadratureRule rule = gauss_legendre(24, 0.0, 1.0);
  for (std::size_t q = 0; q < rule.nodes.size(); ++q) rule.weights[q] *= 2.0 * rule.nodes[q];
  return rule;
}

LateralTopInterface lateral_top_interface(const RoughDielectric& top, int ordinates, int modes, Incidence incidence,
                                          int azimuths) {
  if (top.eta == 1.0) throw std::invalid_argument("lateral_top_interface: eta = 1 is no interface");
  LayerGeometry geometry;
  geometry.top_open = false;
  geometry.top = top;
  geometry.base = LayerBase::Open;  // the bottom's operators are not wanted here
  const QuadratureRule incident =
      incidence == Incidence::Normal ? QuadratureRule{{1.0}, {1.0}} : diffuse_incidence_cosines();
  const InterfaceKernels kernels = interface_kernels(geometry, ordinates, modes, azimuths, incident.nodes, {});
  LateralTopInterface interface;
  interface.reflection = kernels.r_top;
  // Mode 0 of each column is its light averaged over the incident azimuths, so diffuse light sums the columns.
  interface.source =
      kernels.t_source.kernel[0] *
      Eigen::Map<const Eigen::VectorXd>(incident.weights.data(), static_cast<Eigen::Index>(incident.size()));
  const Eigen::Index n = kernels.quadrature.size();
  interface.exit.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    interface.exit(j) = kernels.top_inside[static_cast<std::size_t>(j)].transmittance;
  }
  for (std::size_t q = 0; q < incident.nodes.size(); ++q) {
    interface.surface_multiple_reflectance += incident.weights[q] * kernels.top_outside[q].multiple.reflectance;
  }
  return interface;
}

LateralTopInterface open_top_diffuse_interface(int ordinates, int modes) {
  LateralTopInterface interface;
  interface.reflection.assign(static_cast<std::size_t>(modes), Eigen::MatrixXd::Zero(ordinates, ordinates));
  interface.source = Eigen::VectorXd::Constant(ordinates, kInvPi);
  interface.exit = Eigen::VectorXd::Ones(ordinates);
  return interface;
}

}  // namespace skinlayer
