// docs/model.md §21.14 and §21.17: a finite stack's bottom face for the lateral solve, from the BSDF solve's operators.
#include "core/spatial/lateral_bottom_face.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/interfaces/fresnel.h"
#include "core/interfaces/interface_albedo.h"
#include "core/interfaces/interface_operators.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/series/quadrature.h"

namespace skinlayer {

LateralBottomFace smooth_bottom_face(double eta, int ordinates, int modes) {
  const LateralSmoothFace face = lateral_smooth_face(eta, ordinates);
  return {std::vector<Eigen::MatrixXd>(static_cast<std::size_t>(modes), Eigen::MatrixXd(face.reflection.asDiagonal())),
          face.exit};
}

LateralBottomFace rough_bottom_face(const RoughDielectric& interface, int ordinates, int modes, int azimuths) {
  if (interface.eta == 1.0) throw std::invalid_argument("rough_bottom_face: eta = 1 is no interface");
  LayerGeometry geometry;
  geometry.top_open = true;  // the top's operators are not wanted here
  geometry.base = LayerBase::Rough;
  geometry.bottom = interface;
  const InterfaceKernels kernels = interface_kernels(geometry, ordinates, modes, azimuths, {}, {});
  LateralBottomFace face{kernels.r_bottom, Eigen::VectorXd(ordinates)};
  for (int j = 0; j < ordinates; ++j) face.exit(j) = kernels.bottom_inside[static_cast<std::size_t>(j)].transmittance;
  return face;
}

LateralBottomFace lambert_bottom_face(double albedo, int ordinates, int modes) {
  if (!(albedo >= 0.0 && albedo <= 1.0)) throw std::invalid_argument("lambert_bottom_face: albedo must be in [0, 1]");
  LateralBottomFace face{
      std::vector<Eigen::MatrixXd>(static_cast<std::size_t>(modes), Eigen::MatrixXd::Zero(ordinates, ordinates)),
      Eigen::VectorXd::Zero(ordinates)};
  face.reflection.front() = lambert_reflection(double_gauss_half_range(ordinates), albedo);
  return face;
}

ExitFraction smooth_exit_fraction(double eta) {
  return [eta](double mu) { return 1.0 - fresnel_dielectric(mu, eta); };
}

ExitFraction rough_exit_fraction(const RoughDielectric& interface) {
  constexpr int kIntervals = 256;
  std::vector<double> cosines(kIntervals + 1);
  for (int i = 0; i <= kIntervals; ++i) cosines[static_cast<std::size_t>(i)] = std::max(1e-4, double(i) / kIntervals);
  const std::vector<InterfaceAlbedo> albedos = totals(interface_albedo_parts_along(interface, cosines, 1.0));
  auto table = std::make_shared<std::vector<double>>();
  for (const InterfaceAlbedo& albedo : albedos) table->push_back(albedo.transmittance);
  return [table](double mu) {
    const double x = std::clamp(mu, 0.0, 1.0) * kIntervals;
    const int i = std::min(kIntervals - 1, static_cast<int>(x));
    const double f = x - i;
    return (1.0 - f) * (*table)[static_cast<std::size_t>(i)] + f * (*table)[static_cast<std::size_t>(i + 1)];
  };
}

}  // namespace skinlayer
