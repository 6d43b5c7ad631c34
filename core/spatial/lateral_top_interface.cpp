// docs/model.md §21.9: the BSDF solve's top operators, for one beam at normal incidence and no exit directions.
#include "core/spatial/lateral_top_interface.h"

#include <stdexcept>

#include "core/interfaces/layer_interfaces.h"

namespace skinlayer {

LateralTopInterface lateral_top_interface(const RoughDielectric& top, int ordinates, int modes, int azimuths) {
  if (top.eta == 1.0) throw std::invalid_argument("lateral_top_interface: eta = 1 is no interface");
  LayerGeometry geometry;
  geometry.top_open = false;
  geometry.top = top;
  geometry.base = LayerBase::Open;  // the bottom's operators are not wanted here
  const double normal[] = {1.0};
  const InterfaceKernels kernels = interface_kernels(geometry, ordinates, modes, azimuths, normal, {});
  LateralTopInterface interface;
  interface.reflection = kernels.r_top;
  interface.source = kernels.t_source.kernel[0].col(0);
  const Eigen::Index n = kernels.quadrature.size();
  interface.exit.resize(n);
  for (Eigen::Index j = 0; j < n; ++j)
    interface.exit(j) = kernels.top_inside[static_cast<std::size_t>(j)].transmittance;
  interface.surface_multiple_reflectance = kernels.top_outside.front().multiple.reflectance;
  return interface;
}

}  // namespace skinlayer
