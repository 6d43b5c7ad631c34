// The Principled parameters of a fit's report (`skinlayer fit --target principled`, or the SKINLAYER_FIT data of an
// exported Blender script), read back for skinlayer's own implementation of the node to evaluate.
#pragma once

#include <nlohmann/json.hpp>

#include "core/targets/principled_bsdf.h"

namespace skinlayer::test {

inline PrincipledParameters principled_parameters(const nlohmann::json& report) {
  const nlohmann::json& p = report.at("parameters");
  PrincipledParameters parameters;
  for (int c = 0; c < 3; ++c) {
    parameters.base_color(c) = p.at("base_color").at(c).get<double>();
    parameters.subsurface_color(c) = p.at("subsurface_color").at(c).get<double>();
    parameters.subsurface_radius(c) = p.at("subsurface_radius").at(c).get<double>();
  }
  parameters.metallic = p.at("metallic");
  parameters.specular = p.at("specular");
  parameters.specular_tint = p.at("specular_tint");
  parameters.roughness = p.at("roughness");
  parameters.sheen = p.at("sheen");
  parameters.sheen_tint = p.at("sheen_tint");
  parameters.clearcoat = p.at("clearcoat");
  parameters.clearcoat_roughness = p.at("clearcoat_roughness");
  parameters.ior = p.at("ior");
  parameters.transmission = p.at("transmission");
  parameters.transmission_roughness = p.at("transmission_roughness");
  parameters.subsurface = p.at("subsurface");
  parameters.subsurface_anisotropy = p.at("subsurface_anisotropy");
  return parameters;
}

}  // namespace skinlayer::test
