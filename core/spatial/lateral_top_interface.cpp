// docs/model.md §21.9 and §21.12: the BSDF solve's top operators, for light at normal incidence or diffuse, and no
// exit directions.
#include "core/spatial/lateral_top_interface.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
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
  interface.multiple = kernels.top_multiple;
  // Mode 0 of each column is its light averaged over the incident azimuths, so diffuse light sums the columns.
  interface.source =
      kernels.t_source.kernel[0] *
      Eigen::Map<const Eigen::VectorXd>(incident.weights.data(), static_cast<Eigen::Index>(incident.size()));
  if (incidence == Incidence::Normal) interface.source_single = kernels.t_source.single_scattering(0).col(0);
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

LateralSmoothFace lateral_smooth_face(double eta, int ordinates) {
  if (!(eta > 0.0 && std::isfinite(eta)))
    throw std::invalid_argument("lateral_smooth_face: eta must be finite and > 0");
  const QuadratureRule q = double_gauss_half_range(ordinates);
  LateralSmoothFace face{Eigen::VectorXd(ordinates), Eigen::VectorXd(ordinates)};
  double escape = 0.0;  // sum_j 2 a_j mu_j (1 - F(mu_j)): what the nodes let out of a diffuse field
  for (int j = 0; j < ordinates; ++j) {
    const double mu = q.nodes[static_cast<std::size_t>(j)];
    face.reflection(j) = fresnel_dielectric(mu, eta);
    face.exit(j) = 1.0 - face.reflection(j);
    escape += 2.0 * q.weights[static_cast<std::size_t>(j)] * mu * face.exit(j);
  }
  // The same from the exact integral, 2 int_0^1 mu (1 - F) d mu on Gauss-Legendre panels split at the critical
  // angle, where 1 - F has its edge. The nodes straddle that edge, and their sum errs by percents, oscillating with
  // N (§21.14). So the operator is matched to it, as §5.3 matches the rough ones: the exits scaled down where the
  // nodes let out too much, the reflectances where they keep too much (each stays in [0, 1]).
  const double critical = eta < 1.0 ? std::sqrt(1.0 - eta * eta) : 0.0;
  double target = 0.0;
  for (const auto& [from, to] : {std::pair{0.0, critical}, std::pair{critical, 1.0}}) {
    if (to <= from) continue;
    target += integrate_mapped(gauss_legendre(64, 0.0, 1.0), from, to,
                               [&](double mu) { return 2.0 * mu * (1.0 - fresnel_dielectric(mu, eta)); });
  }
  if (escape > target) {
    face.exit *= target / escape;
    face.reflection = Eigen::VectorXd::Ones(ordinates) - face.exit;
  } else {
    face.reflection *= (1.0 - target) / (1.0 - escape);
    face.exit = Eigen::VectorXd::Ones(ordinates) - face.reflection;
  }
  return face;
}

LateralTopInterface smooth_top_interface(double eta, int ordinates, int modes) {
  const LateralSmoothFace inside = lateral_smooth_face(1.0 / eta, ordinates);
  LateralTopInterface interface;
  interface.reflection.assign(static_cast<std::size_t>(modes), Eigen::MatrixXd(inside.reflection.asDiagonal()));
  interface.source = Eigen::VectorXd::Zero(ordinates);
  interface.exit = inside.exit;
  interface.collimated = 1.0 - fresnel_dielectric(1.0, eta);
  return interface;
}

LateralTopInterface open_top_interface(int ordinates, int modes, Incidence incidence) {
  const bool diffuse = incidence == Incidence::Diffuse;
  LateralTopInterface interface;
  interface.reflection.assign(static_cast<std::size_t>(modes), Eigen::MatrixXd::Zero(ordinates, ordinates));
  interface.source = Eigen::VectorXd::Constant(ordinates, diffuse ? kInvPi : 0.0);
  interface.exit = Eigen::VectorXd::Ones(ordinates);
  interface.collimated = diffuse ? 0.0 : 1.0;
  return interface;
}

}  // namespace skinlayer
