// What a picture skinlayer wrote remembers: its material file and the light and view settings it was drawn with,
// as JSON in the PNG's iTXt chunk "skinlayer-material":
//
//   {"format": "skinlayer-picture", "version": 1,
//    "material": {...a material file (material_json.h)...},
//    "settings": {...how it was drawn: light, view, exposure, size; or a figure's name and varied parameter...}}
//
// `--material shot.png` reads the material back (material_file.h).
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

#include "app/material/material_document.h"
#include "app/material/png_codec.h"

namespace skinlayer {

inline constexpr std::string_view kPictureChunkKeyword = "skinlayer-material";
inline constexpr std::string_view kPictureFormat = "skinlayer-picture";

// The chunk for a picture of `material` drawn with `settings` (a JSON object).
PngText picture_metadata(const MaterialDocument& material, const nlohmann::ordered_json& settings);

// The material of a PNG's bytes. Throws MaterialFileError naming `source`: not a PNG skinlayer wrote (no chunk), a
// damaged PNG, or a chunk that is not a picture's metadata or holds a bad material.
MaterialDocument material_from_picture(std::string_view png_bytes, std::string_view source);

}  // namespace skinlayer
