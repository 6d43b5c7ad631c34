// Writes a preset's glTF export for the tests that run the real glTF tools (tests/app/export/gltf_validate.mjs,
// gltf_three_furnace.mjs), until `skinlayer export --format gltf` is wired: gltf_write_preset <preset> <file.gltf>.
// Prints one JSON line: the preset, the document's own albedo at normal incidence (skinlayer albedo's), and the
// fitted glTF model's (core/targets/gltf_pbr.h), linear RGB.
// gltf_write_preset --parameters '<JSON>' <file.gltf> writes a material given by its factors instead, no fit
// ({"base_color": [r, g, b], "roughness": ..., "sheen_color": [...], ...}: GltfPbrParameters' names; the rest
// glTF's defaults), with the model's albedos in the extras as the export has them: for furnace tests of the
// extensions a fit seldom uses.
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/export/gltf_export.h"
#include "app/material/presets.h"
#include "app/process/parallel_for.h"
#include "app/solution/document_albedo.h"
#include "app/solution/gltf_fit_document.h"

int main(int argc, char** argv) {
  using namespace skinlayer;
  if (argc != 3 && !(argc == 4 && std::string(argv[1]) == "--parameters")) {
    std::fprintf(stderr, "usage: gltf_write_preset <preset> <file.gltf> | --parameters <JSON> <file.gltf>\n");
    return 2;
  }
  try {
    if (std::string(argv[1]) == "--parameters") {
      const nlohmann::json given = nlohmann::json::parse(argv[2]);
      const auto color = [&](const char* key, Rgb fallback) {
        return given.contains(key) ? Rgb(given[key][0], given[key][1], given[key][2]) : fallback;
      };
      GltfPbrParameters p;
      p.base_color = color("base_color", p.base_color);
      p.metallic = given.value("metallic", p.metallic);
      p.roughness = given.value("roughness", p.roughness);
      p.ior = given.value("ior", p.ior);
      p.specular = given.value("specular", p.specular);
      p.specular_color = color("specular_color", p.specular_color);
      p.sheen_color = color("sheen_color", p.sheen_color);
      p.sheen_roughness = given.value("sheen_roughness", p.sheen_roughness);
      p.clearcoat = given.value("clearcoat", p.clearcoat);
      p.clearcoat_roughness = given.value("clearcoat_roughness", p.clearcoat_roughness);
      const GltfPbr model(p);
      nlohmann::ordered_json off_normal;
      for (const int degrees : {30, 60}) {
        const Rgb albedo = model.albedo(std::cos(degrees * 3.14159265358979323846 / 180.0));
        off_normal[std::to_string(degrees)] = {albedo(0), albedo(1), albedo(2)};
      }
      const Rgb at_normal = model.albedo(1.0);
      const nlohmann::ordered_json extras = {
          {"gltf_model_albedo_at_normal_incidence", {at_normal(0), at_normal(1), at_normal(2)}},
          {"gltf_model_albedo_at_degrees", off_normal}};
      std::ofstream(argv[3]) << gltf_asset(p, "parameters", extras).dump(2) << "\n";
      std::printf("%s\n", extras.dump().c_str());
      return 0;
    }
    const MaterialDocument document = preset_material(argv[1]);
    const DocumentFit<GltfFit> fit = fit_gltf(document, parallel_for_threads);
    std::ofstream(argv[2]) << gltf_export(document, fit);
    const double normal[] = {0.0};
    const Rgb model = GltfPbr(fit.fit.parameters).albedo(1.0);
    const Rgb own = document_reflectance_rgb(document, normal, parallel_for_threads).front();
    const nlohmann::ordered_json line = {{"preset", argv[1]},
                                         {"skinlayer_albedo_0", {own(0), own(1), own(2)}},
                                         {"gltf_model_albedo_0", {model(0), model(1), model(2)}},
                                         {"fit", gltf_fit_json(fit)}};
    std::printf("%s\n", line.dump().c_str());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "gltf_write_preset: %s\n", error.what());
    return 1;
  }
  return 0;
}
