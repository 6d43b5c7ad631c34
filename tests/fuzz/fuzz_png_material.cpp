// Fuzz target: a PNG that carries a material in its skinlayer-material text chunk (app/material/picture_metadata.h,
// libpng underneath). The material it yields must save and read back as itself.
#include "app/material/picture_metadata.h"
#include "tests/fuzz/material_round_trip.h"

using namespace skinlayer;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  MaterialDocument document;
  if (fuzz::refused_cleanly<MaterialFileError>(
          [&] { document = material_from_picture(fuzz::input_bytes(data, size), "fuzz.png"); }))
    return 0;
  fuzz::require_reads_back_once_saved(document);
  return 0;
}
