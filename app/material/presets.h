// The named presets: the material files of app/presets/, embedded at build time (shaders/embed_text.cmake), each
// with its name (the file's, without .json) and a one-line description.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "app/material/material_document.h"

namespace skinlayer {

struct PresetInfo {
  std::string name;
  std::string description;
};

// Every preset's name, in order (no file is parsed).
std::vector<std::string> preset_names();

// Every preset, in name order, with its description (each file parsed).
std::vector<PresetInfo> preset_list();

// The preset's material. Throws MaterialFileError for an unknown name, listing the known ones.
MaterialDocument preset_material(std::string_view name);

}  // namespace skinlayer
