// Material files on disk: a JSON material file (material_json.h), or a PNG that skinlayer wrote, whose
// skinlayer-material chunk holds one (picture_metadata.h).
#pragma once

#include <string>

#include "app/material/material_document.h"

namespace skinlayer {

// Reads a material file or picture. Throws MaterialFileError naming the path: unreadable, not JSON (line:column),
// not a material, a PNG without skinlayer's chunk, or any of read_material_json's errors.
MaterialDocument read_material_file(const std::string& path);

// Writes material_json_text atomically (atomic_file.h). Throws std::runtime_error naming the path.
void write_material_file(const MaterialDocument& document, const std::string& path);

}  // namespace skinlayer
