#include "app/preview/preview_state.h"

#include <cmath>

#include "core/conventions.h"
#include "core/material.h"

namespace skinlayer {

ColorMaterial paper_default_material() {
  ColorMaterial material;
  material.layer.sigma = parameter_info("sigma").default_value;
  material.layer.eta = parameter_info("eta").default_value;
  material.layer.tau = optical_depth_from_transparency(parameter_info("T").default_value);
  material.layer.g = parameter_info("g").default_value;
  const double albedo = parameter_info("albedo").default_value;
  material.layer.albedo = albedo;
  material.albedo_rgb = {albedo, albedo, albedo};
  material.layer.bottom = Bottom{};  // air, with the top's sigma and eta
  material.layer.ordinates.reset();  // automatic
  return material;
}

PreviewState reset_material(PreviewState state) {
  state.material = paper_default_material();
  return state;
}

SolveRequest solve_request(const PreviewState& state) {
  return SolveRequest{state.material, degrees_to_radians(state.light.theta_degrees),
                      state.view.view == ViewKind::Compare, state.view.plot_model.value_or(state.material.model)};
}

double exposure_multiplier(const ViewOptions& view) { return std::exp2(view.exposure_stops); }

EnvironmentView LightingState::view() const {
  return EnvironmentView{degrees_to_radians(rotate_degrees), std::exp2(ev), background};
}

}  // namespace skinlayer
