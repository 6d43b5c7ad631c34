#include "app/material/material_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string_view>

#include "app/export/scatfun_file.h"
#include "app/material/atomic_file.h"
#include "app/material/material_json.h"
#include "app/material/picture_metadata.h"
#include "app/material/png_codec.h"

namespace skinlayer {

namespace {

// What an export of skinlayer's is, for a file given where a material was asked for (none for anything else).
std::optional<std::string_view> export_kind(std::string_view bytes) {
  const std::string_view head = bytes.substr(0, 4096);  // past the exports' header comments
  if (bytes.starts_with(std::string_view("tensor_file\0", 12))) return "a tensor file (export --format rgl)";
  if (head.find("<materialx") != std::string_view::npos) return "a MaterialX document (export --format mtlx)";
  if (head.find("\nimport bpy") != std::string_view::npos) return "a Blender script (export --format blender)";
  if (head.find("\"asset\"") != std::string_view::npos && head.find("\"generator\"") != std::string_view::npos) {
    return "a glTF file (export --format gltf)";
  }
  return std::nullopt;
}

}  // namespace

MaterialDocument read_material_file(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw MaterialFileMissing(path + " is a folder, not a material file", MaterialFileMissing::Kind::kFolder);
  }
  std::ifstream file(path, std::ios::binary);
  if (!file && errno == ENOENT) {
    throw MaterialFileMissing("cannot read " + path + ": no such file", MaterialFileMissing::Kind::kNoSuchFile);
  }
  if (!file) throw MaterialFileError("cannot read " + path + ": " + std::strerror(errno));
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) throw MaterialFileError("cannot read " + path + ": " + std::strerror(errno));
  return read_material_bytes(bytes, path);
}

MaterialDocument read_material_bytes(std::string_view bytes, std::string_view source) {
  if (is_png(bytes)) return material_from_picture(bytes, source);
  if (const std::optional<std::string_view> kind = export_kind(bytes)) {
    throw MaterialFileError(std::string(source) + " is " + std::string(*kind) +
                            ", not a material: give the material's .json, a picture skinlayer wrote, or a .bsdf "
                            "export, which carry it");
  }
  if (is_scatfun(bytes)) {
    const std::string name(source);
    const std::optional<std::string_view> metadata = scatfun_metadata(bytes);
    if (!metadata) throw MaterialFileError(name + " is a damaged SCATFUN file (shorter than its header says)");
    if (metadata->empty()) throw MaterialFileError(name + " is a SCATFUN file without a material (no metadata)");
    return read_material_json(*metadata, source);
  }
  return read_material_json(bytes, source);
}

void write_material_file(const MaterialDocument& document, const std::string& path) {
  write_file_atomically(path, material_json_text(document));
}

}  // namespace skinlayer
