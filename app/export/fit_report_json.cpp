#include "app/export/fit_report_json.h"

#include <cmath>

#include "core/conventions.h"

namespace skinlayer {
namespace {

nlohmann::ordered_json channels(const Rgb& values) { return {values(0), values(1), values(2)}; }

// The report around the parameters: where the radius came from, the albedo's match and the errors.
nlohmann::ordered_json report(const char* target, const char* renderer, const nlohmann::ordered_json& parameters,
                              const std::string& radius_source, bool albedo_matched, const Rgb& albedo_miss,
                              const FitErrors& fit_errors) {
  nlohmann::ordered_json errors;
  errors["lobe_rms"] = channels(fit_errors.lobe_rms);
  errors["lobe_worst"] = channels(fit_errors.lobe_worst);
  errors["albedo_rms"] = channels(fit_errors.albedo_rms);
  errors["albedo_worst"] = channels(fit_errors.albedo_worst);
  nlohmann::ordered_json json;
  json["target"] = target;
  json["renderer"] = renderer;
  json["parameters"] = parameters;
  json["subsurface_radius_source"] = radius_source;
  json["albedo_matched_at_normal_incidence"] = albedo_matched;
  json["albedo_miss_at_normal_incidence"] = channels(albedo_miss);
  json["errors"] = errors;
  nlohmann::ordered_json albedo;
  albedo["degrees"] = nlohmann::ordered_json::array();
  albedo["fitted"] = nlohmann::ordered_json::array();
  albedo["material"] = nlohmann::ordered_json::array();
  for (std::size_t a = 0; a < fit_errors.albedo_angles.size(); ++a) {
    albedo["degrees"].push_back(std::round(radians_to_degrees(fit_errors.albedo_angles[a]) * 1e6) / 1e6);
    albedo["fitted"].push_back(channels(fit_errors.albedo_fitted[a]));
    albedo["material"].push_back(channels(fit_errors.albedo_target[a]));
  }
  json["albedo"] = albedo;  // under a white sky, at each angle of the view (or of the light, for a reciprocal shader)
  return json;
}

}  // namespace

nlohmann::ordered_json principled_fit_json(const DocumentFit<CyclesPrincipledFit>& fit) {
  const CyclesPrincipledParameters& p = fit.fit.parameters;
  nlohmann::ordered_json parameters;
  parameters["base_color"] = channels(p.base_color);
  parameters["metallic"] = p.metallic;
  parameters["roughness"] = p.roughness;
  parameters["ior"] = p.ior;
  parameters["diffuse_roughness"] = p.diffuse_roughness;
  parameters["subsurface_weight"] = p.subsurface_weight;
  parameters["subsurface_radius"] = channels(p.subsurface_radius);
  parameters["subsurface_scale"] = p.subsurface_scale;
  parameters["subsurface_anisotropy"] = p.subsurface_anisotropy;
  parameters["specular_ior_level"] = p.specular_ior_level;
  parameters["specular_tint"] = channels(p.specular_tint);
  parameters["transmission_weight"] = p.transmission_weight;
  parameters["coat_weight"] = p.coat_weight;
  parameters["coat_roughness"] = p.coat_roughness;
  parameters["coat_ior"] = p.coat_ior;
  parameters["coat_tint"] = channels(p.coat_tint);
  parameters["sheen_weight"] = p.sheen_weight;
  parameters["sheen_roughness"] = p.sheen_roughness;
  parameters["sheen_tint"] = channels(p.sheen_tint);
  parameters["distribution"] =
      p.distribution == CyclesDistribution::kMultiscatterGgx ? "MULTI_GGX" : "GGX";  // Blender's enum names
  return report(
      "principled",
      "Blender 4.2-5.x (Cycles), Principled BSDF, distribution Multiscatter GGX; Diffuse Roughness needs 4.3; "
      "a coat as 4.4+ renders it (4.2-4.3's coat keeps less light at grazing views)",
      parameters, fit.radius_source, fit.fit.albedo_matched, fit.fit.albedo_miss, fit.fit.errors);
}

nlohmann::ordered_json principled_3_4_fit_json(const DocumentFit<PrincipledFit>& fit) {
  const PrincipledParameters& p = fit.fit.parameters;
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
  parameters["ior"] = p.ior;
  parameters["transmission"] = p.transmission;
  parameters["transmission_roughness"] = p.transmission_roughness;
  parameters["subsurface"] = p.subsurface;
  parameters["subsurface_color"] = channels(p.subsurface_color);
  parameters["subsurface_radius"] = channels(p.subsurface_radius);
  parameters["subsurface_anisotropy"] = p.subsurface_anisotropy;
  return report("principled-3.4", "Blender 3.4 (Cycles), Principled BSDF, distribution GGX", parameters,
                fit.radius_source, fit.fit.albedo_matched, fit.fit.albedo_miss, fit.fit.errors);
}

nlohmann::ordered_json openpbr_fit_json(const DocumentFit<OpenPbrFit>& fit) {
  const OpenPbrParameters& p = fit.fit.parameters;
  nlohmann::ordered_json parameters;
  parameters["base_weight"] = p.base_weight;
  parameters["base_color"] = channels(p.base_color);
  parameters["base_diffuse_roughness"] = p.base_diffuse_roughness;
  parameters["base_metalness"] = p.base_metalness;
  parameters["specular_weight"] = p.specular_weight;
  parameters["specular_color"] = channels(p.specular_color);
  parameters["specular_roughness"] = p.specular_roughness;
  parameters["specular_ior"] = p.specular_ior;
  parameters["subsurface_weight"] = p.subsurface_weight;
  parameters["subsurface_color"] = channels(p.subsurface_color);
  parameters["subsurface_radius"] = p.subsurface_radius;
  parameters["subsurface_radius_scale"] = channels(p.subsurface_radius_scale);
  parameters["subsurface_scatter_anisotropy"] = p.subsurface_scatter_anisotropy;
  parameters["fuzz_weight"] = p.fuzz_weight;
  parameters["fuzz_color"] = channels(p.fuzz_color);
  parameters["fuzz_roughness"] = p.fuzz_roughness;
  parameters["coat_weight"] = p.coat_weight;
  parameters["coat_color"] = channels(p.coat_color);
  parameters["coat_roughness"] = p.coat_roughness;
  parameters["coat_ior"] = p.coat_ior;
  parameters["coat_darkening"] = p.coat_darkening;
  return report("openpbr", "OpenPBR Surface 1.1 (MaterialX 1.39), subsurface_radius in millimetres", parameters,
                fit.radius_source, fit.fit.albedo_matched, fit.fit.albedo_miss, fit.fit.errors);
}

nlohmann::ordered_json gltf_fit_json(const DocumentFit<GltfFit>& fit) {
  const GltfPbrParameters& p = fit.fit.parameters;
  nlohmann::ordered_json parameters;
  parameters["base_color"] = channels(p.base_color);
  parameters["metallic"] = p.metallic;
  parameters["roughness"] = p.roughness;
  parameters["ior"] = p.ior;
  parameters["specular"] = p.specular;
  parameters["specular_color"] = channels(p.specular_color);
  parameters["sheen_color"] = channels(p.sheen_color);
  parameters["sheen_roughness"] = p.sheen_roughness;
  parameters["clearcoat"] = p.clearcoat;
  parameters["clearcoat_roughness"] = p.clearcoat_roughness;
  return report("gltf",
                "glTF 2.0 metallic-roughness (Appendix B) with KHR_materials_ior, _specular, _sheen and _clearcoat; "
                "the renderer's choices as three.js r187's",
                parameters, fit.radius_source, fit.fit.albedo_matched, fit.fit.albedo_miss, fit.fit.errors);
}

}  // namespace skinlayer
