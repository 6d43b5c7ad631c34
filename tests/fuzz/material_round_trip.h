// For the fuzz targets of the material readers: a document that was read saves as JSON and reads back as itself
// (material_json_text is a fixed point), else fuzz_failure.
#pragma once

#include <string>

#include "app/material/material_json.h"
#include "tests/fuzz/fuzz_target.h"

namespace skinlayer::fuzz {

inline void require_reads_back_once_saved(const MaterialDocument& document) {
  const std::string saved = material_json_text(document);
  MaterialDocument again;
  if (refused_cleanly<MaterialFileError>([&] { again = read_material_json(saved, "saved.json"); })) {
    fuzz_failure("a material that was read does not read back once saved:\n" + saved);
  }
  require(material_json_text(again) == saved, "a material saved twice is not the same text:\n" + saved);
}

}  // namespace skinlayer::fuzz
