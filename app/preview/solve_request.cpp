#include "app/preview/solve_request.h"

namespace skinlayer {
namespace {

bool same_bottom(const Bottom& a, const Bottom& b) {
  return a.kind == b.kind && a.sigma == b.sigma && a.eta == b.eta && a.lambert_albedo == b.lambert_albedo;
}

bool same_layer(const Material& a, const Material& b) {
  return a.sigma == b.sigma && a.eta == b.eta && a.tau == b.tau && a.g == b.g && same_bottom(a.bottom, b.bottom) &&
         a.ordinates == b.ordinates;
}

}  // namespace

bool same_request(const SolveRequest& a, const SolveRequest& b) {
  return same_layer(a.material.layer, b.material.layer) && a.material.albedo_rgb == b.material.albedo_rgb &&
         a.material.model == b.material.model && a.theta_i == b.theta_i && a.compare == b.compare &&
         a.plot_model == b.plot_model;
}

std::array<bool, 3> needed_models(const SolveRequest& request) {
  std::array<bool, 3> needed{};
  needed[static_cast<std::size_t>(request.material.model)] = true;
  needed[static_cast<std::size_t>(request.plot_model)] = true;
  if (request.compare) needed = {true, true, true};
  return needed;
}

}  // namespace skinlayer
