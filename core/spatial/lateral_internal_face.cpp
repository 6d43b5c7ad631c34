// docs/model.md §21.16: the BSDF solve's operators of an interface between stacked layers, for the lateral solve.
#include "core/spatial/lateral_internal_face.h"

#include <stdexcept>

#include "core/interfaces/internal_interface.h"
#include "core/series/quadrature.h"

namespace skinlayer {

LateralInternalFace lateral_internal_face(const RoughDielectric& interface, int ordinates, int modes, int azimuths) {
  if (interface.eta == 1.0) throw std::invalid_argument("lateral_internal_face: eta = 1 is no interface");
  const InternalInterfaceKernels kernels = internal_interface_kernels(
      interface, double_gauss_half_range(ordinates), modes, azimuths, {}, {}, InternalInterfaceNeeds{});
  return {kernels.reflect_above, kernels.reflect_below, kernels.transmit_down, kernels.transmit_up};
}

}  // namespace skinlayer
