// Material files on disk: a JSON material file (material_json.h), a PNG that skinlayer wrote, whose
// skinlayer-material chunk holds one (picture_metadata.h), or a .bsdf (SCATFUN) file whose metadata holds one
// (app/export/scatfun_file.h).
#pragma once

#include <string>
#include <string_view>

#include "app/material/material_document.h"

namespace skinlayer {

// Reads a material file or picture. Throws MaterialFileError naming the path: unreadable, not JSON (line:column),
// not a material, a PNG without skinlayer's chunk, or any of read_material_json's errors.
MaterialDocument read_material_file(const std::string& path);
// The same from the file's bytes; `source` names it in errors.
MaterialDocument read_material_bytes(std::string_view bytes, std::string_view source);

// Writes material_json_text atomically (atomic_file.h). Throws std::runtime_error naming the path.
void write_material_file(const MaterialDocument& document, const std::string& path);

}  // namespace skinlayer
