#include "app/preview/solve_request.h"

namespace skinlayer {

bool same_request(const SolveRequest& a, const SolveRequest& b) {
  // layer.albedo (and each stacked layer's) is not solved; the RGB albedos are, or a skin's parameters.
  return differ_only_in_albedos(a.material.layer, b.material.layer) && a.material.albedo_rgb == b.material.albedo_rgb &&
         a.material.below_rgb == b.material.below_rgb && a.material.model == b.material.model &&
         a.material.skin == b.material.skin &&
         a.theta_i == b.theta_i && a.compare == b.compare && a.plot_model == b.plot_model;
}

std::array<bool, 3> needed_models(const SolveRequest& request) {
  std::array<bool, 3> needed{};
  needed[static_cast<std::size_t>(request.material.model)] = true;
  needed[static_cast<std::size_t>(request.plot_model)] = true;
  if (request.compare) needed = {true, true, true};
  return needed;
}

}  // namespace skinlayer
