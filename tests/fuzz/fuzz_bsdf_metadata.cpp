// Fuzz target: the material loader on a .bsdf (SCATFUN) file, whose trailing metadata is a material JSON
// (app/material/material_file.h: read_material_bytes, the dispatch that `--material FILE` and Material.load use).
#include "app/export/scatfun_file.h"
#include "app/material/material_file.h"
#include "tests/fuzz/material_round_trip.h"

using namespace skinlayer;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = fuzz::input_bytes(data, size);
  // The metadata, when the header's size fits, is the file's tail.
  if (const std::optional<std::string_view> metadata = scatfun_metadata(bytes)) {
    fuzz::require(metadata->size() <= size && metadata->data() + metadata->size() == bytes.data() + size,
                  "scatfun_metadata is not the file's tail");
  }
  MaterialDocument document;
  if (fuzz::refused_cleanly<MaterialFileError>([&] { document = read_material_bytes(bytes, "fuzz.bsdf"); })) return 0;
  fuzz::require_reads_back_once_saved(document);
  return 0;
}
