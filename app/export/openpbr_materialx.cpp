#include "app/export/openpbr_materialx.h"

#include <cctype>
#include <cstdio>
#include <pugixml.hpp>
#include <sstream>

#include "app/export/fit_report_json.h"
#include "app/material/material_json.h"
#include "app/text/numbers.h"

namespace skinlayer {
namespace {

std::string number(double value) { return text::format_shortest(value); }  // reads back to the last bit

std::string color(const Rgb& value) { return number(value(0)) + ", " + number(value(1)) + ", " + number(value(2)); }

pugi::xml_node input(pugi::xml_node node, const char* name, const char* type, const std::string& value) {
  pugi::xml_node in = node.append_child("input");
  in.append_attribute("name") = name;
  in.append_attribute("type") = type;
  in.append_attribute("value") = value.c_str();
  return in;
}

}  // namespace

std::string materialx_identifier(const std::string& name) {
  std::string id;
  for (const char c : name) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  if (id.empty()) return "skinlayer";
  if (std::isdigit(static_cast<unsigned char>(id.front()))) id = "m_" + id;
  return id;
}

std::string openpbr_materialx(const MaterialDocument& document, const DocumentFit<OpenPbrFit>& fit) {
  const OpenPbrParameters& p = fit.fit.parameters;
  const std::string name = materialx_identifier(document.name), shader_name = "SR_" + name;
  pugi::xml_document xml;
  const FitErrors& e = fit.fit.errors;
  char summary[512];
  std::snprintf(
      summary, sizeof summary,
      " OpenPBR Surface fitted by skinlayer (its fit command, target openpbr). Its error, red green blue,\n"
      "     relative to the material's own values: cosine-weighted BRDF, light 0-80 degrees, RMS %.1f%% %.1f%%"
      " %.1f%%,\n     worst %.1f%% %.1f%% %.1f%%; directional albedo 0-80 degrees, worst %.1f%% %.1f%% %.1f%%.\n"
      "     The fit's report and the material ride along as the nodes' doc strings. ",
      100 * e.lobe_rms(0), 100 * e.lobe_rms(1), 100 * e.lobe_rms(2), 100 * e.lobe_worst(0), 100 * e.lobe_worst(1),
      100 * e.lobe_worst(2), 100 * e.albedo_worst(0), 100 * e.albedo_worst(1), 100 * e.albedo_worst(2));
  xml.append_child(pugi::node_comment).set_value(summary);
  pugi::xml_node root = xml.append_child("materialx");
  root.append_attribute("version") = "1.39";
  root.append_attribute("colorspace") = "lin_rec709";

  pugi::xml_node shader = root.append_child("open_pbr_surface");
  shader.append_attribute("name") = shader_name.c_str();
  shader.append_attribute("type") = "surfaceshader";
  shader.append_attribute("doc") = ("skinlayer fit " + openpbr_fit_json(fit).dump()).c_str();
  input(shader, "base_weight", "float", number(p.base_weight));
  input(shader, "base_color", "color3", color(p.base_color));
  input(shader, "base_diffuse_roughness", "float", number(p.base_diffuse_roughness));
  input(shader, "base_metalness", "float", number(p.base_metalness));
  input(shader, "specular_weight", "float", number(p.specular_weight));
  input(shader, "specular_color", "color3", color(p.specular_color));
  input(shader, "specular_roughness", "float", number(p.specular_roughness));
  input(shader, "specular_ior", "float", number(p.specular_ior));
  input(shader, "subsurface_weight", "float", number(p.subsurface_weight));
  input(shader, "subsurface_color", "color3", color(p.subsurface_color));
  pugi::xml_node radius = input(shader, "subsurface_radius", "float", number(p.subsurface_radius));
  radius.append_attribute("unittype") = "distance";
  radius.append_attribute("unit") = "millimeter";
  input(shader, "subsurface_radius_scale", "color3", color(p.subsurface_radius_scale));
  input(shader, "subsurface_scatter_anisotropy", "float", number(p.subsurface_scatter_anisotropy));
  input(shader, "fuzz_weight", "float", number(p.fuzz_weight));
  input(shader, "fuzz_color", "color3", color(p.fuzz_color));
  input(shader, "fuzz_roughness", "float", number(p.fuzz_roughness));
  input(shader, "coat_weight", "float", number(p.coat_weight));
  input(shader, "coat_color", "color3", color(p.coat_color));
  input(shader, "coat_roughness", "float", number(p.coat_roughness));
  input(shader, "coat_ior", "float", number(p.coat_ior));
  input(shader, "coat_darkening", "float", number(p.coat_darkening));

  pugi::xml_node material = root.append_child("surfacematerial");
  material.append_attribute("name") = name.c_str();
  material.append_attribute("type") = "material";
  material.append_attribute("doc") = ("skinlayer " + material_json(document).dump()).c_str();
  pugi::xml_node surface = material.append_child("input");
  surface.append_attribute("name") = "surfaceshader";
  surface.append_attribute("type") = "surfaceshader";
  surface.append_attribute("nodename") = shader_name.c_str();

  std::ostringstream out;
  xml.save(out, "  ", pugi::format_default | pugi::format_no_declaration);
  return "<?xml version=\"1.0\"?>\n" + out.str();
}

}  // namespace skinlayer
