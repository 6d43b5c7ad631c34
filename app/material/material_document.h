// A material as a file holds it (docs/guide/material-files.md): the layer parameters with a grey or RGB albedo,
// the subsurface model, and a name and a one-line description. The value the JSON reader and writer
// (material_json.h), the presets (presets.h), the command line's --material and --preset and the previewer share.
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/material.h"
#include "core/models/subsurface_model.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer {

using AlbedoRgb = std::array<double, 3>;

struct MaterialDocument {
  std::string name;         // empty: none
  std::string description;  // empty: none
  Material layer;           // layer.albedo is albedo_rgb[0]; layer.below[i].albedo is below_rgb[i][0]
  AlbedoRgb albedo_rgb = {1.0, 1.0, 1.0};
  std::vector<AlbedoRgb> below_rgb;      // a stack's layers 2..n, one per layer.below
  std::optional<SubsurfaceModel> model;  // unset: the command's default (stam)
  // A biophysical skin (--skin): its layers per wavelength come from these parameters (core/skin/skin_optics.h),
  // and `layer` keeps only the top interface (sigma, eta) and the ordinates. Unset: the layers above.
  std::optional<SkinParameters> skin;

  // Every layer's albedo is the same in the three channels (never for a skin: it is spectral).
  bool grey() const;
  // The material of one channel (0 red, 1 green, 2 blue): every layer's albedo that channel's.
  Material channel(int c) const;
  // Sets layer i's (0-based, top to bottom) albedo in the three channels, and layer.albedo or layer.below[i - 1].
  void set_layer_albedo(std::size_t i, const AlbedoRgb& rgb);
  // Layer i's albedo in the three channels (a stacked layer without below_rgb: its grey albedo).
  AlbedoRgb layer_albedo(std::size_t i) const;
};

// The document's three channels as the distinct materials to solve: channel c (0 red, 1 green, 2 blue) is
// materials[index[c]]. Channels whose layers' albedos are equal share one material, so a grey document has one.
struct DistinctChannels {
  std::vector<Material> materials;
  std::array<std::size_t, 3> index{};
};
DistinctChannels distinct_channels(const MaterialDocument& document);

// Throws MaterialFileError unless the document is a layered one: `what` (a function that works on a document's
// layers, as distinct_channels) cannot take a spectral skin, whose colour is solved per wavelength instead
// (app/material/color_channels.h).
void require_layered(const MaterialDocument& document, std::string_view what);

// The document of a one-channel material: every layer's albedo the same in the three channels.
MaterialDocument grey_document(const Material& material);

// A skin document at one wavelength: its layers there as a grey document, with its name, description and model.
// The document must be a skin's (document.skin set).
MaterialDocument skin_document_at_wavelength(const MaterialDocument& skin, double wavelength_nm);

// A material file (or preset, or picture) that cannot be read. The message is one line that names the file and,
// as the case may be, line:column of a syntax error or the key at fault with what would be valid. The command line
// exits with status 2, as for a bad flag. Whatever of the file the message quotes is made printable
// (app/text/quoted.h: no control characters, valid UTF-8), so that a hostile file cannot break the line.
class MaterialFileError : public std::runtime_error {
 public:
  explicit MaterialFileError(const std::string& message);
};

// The file is not there, or is a folder: a MaterialFileError that Python raises as FileNotFoundError or
// IsADirectoryError.
class MaterialFileMissing : public MaterialFileError {
 public:
  enum class Kind { kNoSuchFile, kFolder };
  MaterialFileMissing(const std::string& message, Kind kind) : MaterialFileError(message), kind_(kind) {}
  Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

}  // namespace skinlayer
