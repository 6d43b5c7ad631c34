#include "app/material/material_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "app/export/scatfun_file.h"
#include "app/material/atomic_file.h"
#include "app/material/material_json.h"
#include "app/material/picture_metadata.h"
#include "app/material/png_codec.h"

namespace skinlayer {

MaterialDocument read_material_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw MaterialFileError("cannot read " + path + ": " + std::strerror(errno));
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) throw MaterialFileError("cannot read " + path + ": " + std::strerror(errno));
  return read_material_bytes(bytes, path);
}

MaterialDocument read_material_bytes(std::string_view bytes, std::string_view source) {
  if (is_png(bytes)) return material_from_picture(bytes, source);
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
