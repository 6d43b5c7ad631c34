#include "app/export/principled_fit_json.h"

namespace skinlayer {
namespace {

nlohmann::ordered_json channels(const Rgb& values) { return {values(0), values(1), values(2)}; }

}  // namespace

nlohmann::ordered_json principled_fit_json(const PrincipledFit& fit) {
  const PrincipledParameters& p = fit.parameters;
  nlohmann::ordered_json parameters;
  parameters["base_color"] = channels(p.base_color);
  parameters["metallic"] = p.metallic;
  parameters["specular"] = p.specular;
  parameters["specular_tint"] = p.specular_tint;
  parameters["roughness"] = p.roughness;
  parameters["sheen"] = p.sheen;
  parameters["sheen_tint"] = p.sheen_tint;
  parameters["clearcoat"] = p.clearcoat;
  parameters["clearcoat_roughness"] = p.clearcoat_roughness;
  parameters["transmission"] = p.transmission;
  parameters["subsurface"] = p.subsurface;
  nlohmann::ordered_json errors;
  errors["lobe_rms"] = channels(fit.errors.lobe_rms);
  errors["lobe_worst"] = channels(fit.errors.lobe_worst);
  errors["albedo_rms"] = channels(fit.errors.albedo_rms);
  errors["albedo_worst"] = channels(fit.errors.albedo_worst);
  nlohmann::ordered_json json;
  json["target"] = "principled";
  json["renderer"] = "Blender 3.4 (Cycles), Principled BSDF, distribution GGX";
  json["parameters"] = parameters;
  json["albedo_matched_at_normal_incidence"] = fit.albedo_matched;
  json["albedo_miss_at_normal_incidence"] = channels(fit.albedo_miss);
  json["errors"] = errors;
  return json;
}

}  // namespace skinlayer
