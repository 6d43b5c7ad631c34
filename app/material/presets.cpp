#include "app/material/presets.h"

#include <algorithm>
#include <span>
#include <string>

#include "app/material/material_json.h"

namespace skinlayer {

// Generated from app/presets/*.json (app/CMakeLists.txt): file name -> text.
std::string_view preset_file(std::string_view name);
std::span<const std::string_view> preset_file_names();

namespace {

constexpr std::string_view kExtension = ".json";

}  // namespace

std::vector<std::string> preset_names() {
  std::vector<std::string> names;
  for (const std::string_view file : preset_file_names()) {
    names.emplace_back(file.substr(0, file.size() - kExtension.size()));
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<PresetInfo> preset_list() {
  std::vector<PresetInfo> list;
  for (const std::string& name : preset_names()) list.push_back({name, preset_material(name).description});
  return list;
}

MaterialDocument preset_material(std::string_view name) {
  const std::vector<std::string> names = preset_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    std::string known;
    for (const std::string& preset : names) known.append(known.empty() ? "" : ", ").append(preset);
    throw MaterialFileError("unknown preset \"" + std::string(name) + "\"; the presets are: " + known);
  }
  const std::string file = std::string(name) + std::string(kExtension);
  return read_material_json(preset_file(file), "preset " + std::string(name) + " (app/presets/" + file + ")");
}

}  // namespace skinlayer
