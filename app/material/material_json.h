// Material files: JSON read and written with nlohmann-json, never by hand. The keys are the command line's flag
// names and the values their values (docs/guide/material-files.md; the schema is app/material/material.schema.json):
//
//   {"format": "skinlayer-material", "version": 1, "name": "...", "description": "...",
//    "top": {"sigma": 0.5, "eta": 1.4},
//    "layers": [{"T": 0.2, "albedo": 1, "g": 0.8}],           // "tau" instead of "T" ("inf" allowed); albedo A or
//                                                             // [r, g, b]; one layer until stacks exist
//    "bottom": {"type": "air", "sigma": 0.5, "eta": 1.4},     // or {"type": "matched"}, {"type": "lambert",
//                                                             // "albedo": A}; air's sigma and eta are optional
//    "ordinates": 32, "model": "stam"}                        // both optional
//
// Every number is checked against core's parameter table, as a flag is.
#pragma once

#include <nlohmann/json_fwd.hpp>  // nlohmann::ordered_json: keys keep the order written
#include <string>
#include <string_view>

#include "app/material/material_document.h"

namespace skinlayer {

inline constexpr std::string_view kMaterialFormat = "skinlayer-material";
inline constexpr int kMaterialVersion = 1;

// The complete document, every value explicit (the bottom's sigma and eta too): T where it reads back to the same
// optical depth, else tau; a grey albedo as one number.
nlohmann::ordered_json material_json(const MaterialDocument& document);

// material_json, indented by two spaces, with a final newline.
std::string material_json_text(const MaterialDocument& document);

// Reads a document. `source` names the file in messages. Throws MaterialFileError: a syntax error with
// source:line:column, an unknown key (listing the valid ones), a wrong type, a missing key, a value out of range
// (core's message), or a format or version this build does not read.
MaterialDocument read_material_json(std::string_view text, std::string_view source);
// The JSON syntax alone: throws MaterialFileError with source:line:column, or for a number past a double's range.
nlohmann::ordered_json parse_json_document(std::string_view text, std::string_view source);
MaterialDocument material_from_json(const nlohmann::ordered_json& json, std::string_view source);

}  // namespace skinlayer
