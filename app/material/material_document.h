// A material as a file holds it (docs: README "Material files"): the layer parameters with a grey or RGB albedo,
// the subsurface model, and a name and a one-line description. The value the JSON reader and writer
// (material_json.h), the presets (presets.h), the command line's --material and --preset and the previewer share.
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/material.h"
#include "core/subsurface_model.h"

namespace skinlayer {

struct MaterialDocument {
  std::string name;         // empty: none
  std::string description;  // empty: none
  Material layer;           // layer.albedo is albedo_rgb[0]
  std::array<double, 3> albedo_rgb = {1.0, 1.0, 1.0};
  std::optional<SubsurfaceModel> model;  // unset: the command's default (stam)

  bool grey() const { return albedo_rgb[0] == albedo_rgb[1] && albedo_rgb[1] == albedo_rgb[2]; }
};

// A material file (or preset, or picture) that cannot be read. The message is one line that names the file and,
// as the case may be, line:column of a syntax error or the key at fault with what would be valid. The command line
// exits with status 2, as for a bad flag.
class MaterialFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace skinlayer
