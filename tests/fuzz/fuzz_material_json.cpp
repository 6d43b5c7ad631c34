// Fuzz target: a material JSON file (app/material/material_json.h). A document that reads must save and read back
// as itself (material_json_text is a fixed point).
#include "tests/fuzz/material_round_trip.h"

using namespace skinlayer;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  MaterialDocument document;
  if (fuzz::refused_cleanly<MaterialFileError>(
          [&] { document = read_material_json(fuzz::input_bytes(data, size), "fuzz.json"); }))
    return 0;
  fuzz::require_reads_back_once_saved(document);
  return 0;
}
