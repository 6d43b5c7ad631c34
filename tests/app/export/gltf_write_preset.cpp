// Writes a preset's glTF export for the tests that run the real glTF tools (tests/app/export/gltf_validate.mjs,
// gltf_three_furnace.mjs), until `skinlayer export --format gltf` is wired: gltf_write_preset <preset> <file.gltf>.
// Prints one JSON line: the preset, the document's own albedo at normal incidence (skinlayer albedo's), and the
// fitted glTF model's (core/targets/gltf_pbr.h), linear RGB.
#include <cstdio>
#include <exception>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/export/gltf_export.h"
#include "app/material/presets.h"
#include "app/process/parallel_for.h"
#include "app/solution/document_albedo.h"
#include "app/solution/gltf_fit_document.h"

int main(int argc, char** argv) {
  using namespace skinlayer;
  if (argc != 3) {
    std::fprintf(stderr, "usage: gltf_write_preset <preset> <file.gltf>\n");
    return 2;
  }
  try {
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
