// The Principled parameters of a fit's report (`skinlayer fit --target principled` or `principled-3.4`, or the
// SKINLAYER_FIT data of an exported Blender script), read back for skinlayer's own implementation of the node to
// evaluate.
#pragma once

#include <nlohmann/json.hpp>

#include "core/targets/cycles_principled.h"
#include "core/targets/principled_bsdf.h"

namespace skinlayer::test {

// Blender 3.4's node ("target": "principled-3.4").
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

inline Rgb rgb_of(const nlohmann::json& values) {
  return Rgb(values.at(0).get<double>(), values.at(1).get<double>(), values.at(2).get<double>());
}

// Blender 4.2-5.x's node ("target": "principled").
inline CyclesPrincipledParameters cycles_principled_parameters(const nlohmann::json& report) {
  const nlohmann::json& p = report.at("parameters");
  CyclesPrincipledParameters parameters;
  parameters.base_color = rgb_of(p.at("base_color"));
  parameters.metallic = p.at("metallic");
  parameters.roughness = p.at("roughness");
  parameters.ior = p.at("ior");
  parameters.diffuse_roughness = p.at("diffuse_roughness");
  parameters.subsurface_weight = p.at("subsurface_weight");
  parameters.subsurface_radius = rgb_of(p.at("subsurface_radius"));
  parameters.subsurface_scale = p.at("subsurface_scale");
  parameters.subsurface_anisotropy = p.at("subsurface_anisotropy");
  parameters.specular_ior_level = p.at("specular_ior_level");
  parameters.specular_tint = rgb_of(p.at("specular_tint"));
  parameters.transmission_weight = p.at("transmission_weight");
  parameters.coat_weight = p.at("coat_weight");
  parameters.coat_roughness = p.at("coat_roughness");
  parameters.coat_ior = p.at("coat_ior");
  parameters.coat_tint = rgb_of(p.at("coat_tint"));
  parameters.sheen_weight = p.at("sheen_weight");
  parameters.sheen_roughness = p.at("sheen_roughness");
  parameters.sheen_tint = rgb_of(p.at("sheen_tint"));
  parameters.distribution =
      p.at("distribution") == "GGX" ? CyclesDistribution::kGgx : CyclesDistribution::kMultiscatterGgx;
  return parameters;
}

}  // namespace skinlayer::test
