#include "app/material/picture_metadata.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "app/material/material_json.h"

namespace skinlayer {

PngText picture_metadata(const MaterialDocument& material, const nlohmann::ordered_json& settings) {
  nlohmann::ordered_json json;
  json["format"] = kPictureFormat;
  json["version"] = 1;
  json["material"] = material_json(material);
  json["settings"] = settings;
  return {std::string(kPictureChunkKeyword), json.dump(2)};
}

MaterialDocument material_from_picture(std::string_view png_bytes, std::string_view source) {
  std::optional<std::string> text;
  try {
    text = read_png_text(png_bytes, kPictureChunkKeyword);
  } catch (const std::runtime_error& error) {
    throw MaterialFileError(std::string(source) + ": " + error.what());
  }
  if (!text) {
    throw MaterialFileError(std::string(source) + ": a PNG without a material (no \"" +
                            std::string(kPictureChunkKeyword) +
                            "\" text chunk); only pictures that skinlayer wrote carry one");
  }
  const std::string chunk = std::string(source) + " (its " + std::string(kPictureChunkKeyword) + " chunk)";
  const nlohmann::ordered_json json = parse_json_document(*text, chunk);
  if (!json.is_object() || !json.contains("format") || json["format"] != kPictureFormat || !json.contains("material")) {
    throw MaterialFileError(chunk + ": not a skinlayer picture's metadata (\"format\": \"" +
                            std::string(kPictureFormat) + "\" with a \"material\")");
  }
  return material_from_json(json["material"], chunk);
}

}  // namespace skinlayer
