#include "app/material/material_document.h"

#include <algorithm>

#include "app/text/quoted.h"
#include "core/skin/skin_optics.h"

namespace skinlayer {

MaterialFileError::MaterialFileError(const std::string& message) : std::runtime_error(text::printable(message)) {}

bool MaterialDocument::grey() const {
  const auto is_grey = [](const AlbedoRgb& rgb) { return rgb[0] == rgb[1] && rgb[1] == rgb[2]; };
  return !skin && is_grey(albedo_rgb) && std::ranges::all_of(below_rgb, is_grey);
}

Material MaterialDocument::channel(int c) const {
  Material m = layer;
  m.albedo = albedo_rgb[static_cast<std::size_t>(c)];
  for (std::size_t i = 0; i < m.below.size() && i < below_rgb.size(); ++i) {
    m.below[i].albedo = below_rgb[i][static_cast<std::size_t>(c)];
  }
  return m;
}

void MaterialDocument::set_layer_albedo(std::size_t i, const AlbedoRgb& rgb) {
  if (i == 0) {
    albedo_rgb = rgb;
    layer.albedo = rgb[0];
    return;
  }
  if (below_rgb.size() < i) below_rgb.resize(i, AlbedoRgb{1.0, 1.0, 1.0});
  below_rgb[i - 1] = rgb;
  layer.below[i - 1].albedo = rgb[0];
}

AlbedoRgb MaterialDocument::layer_albedo(std::size_t i) const {
  if (i == 0) return albedo_rgb;
  if (i <= below_rgb.size()) return below_rgb[i - 1];
  const double grey = layer.below[i - 1].albedo;
  return {grey, grey, grey};
}

void require_layered(const MaterialDocument& document, std::string_view what) {
  if (!document.skin) return;
  throw MaterialFileError((document.name.empty() ? std::string("the material") : "material " + document.name) +
                          " is a spectral skin (a \"skin\" block or --skin), which " + std::string(what) +
                          " cannot take: it has no channels of its own, only a spectrum (color_channels)");
}

DistinctChannels distinct_channels(const MaterialDocument& document) {
  require_layered(document, "distinct_channels");
  DistinctChannels channels;
  for (std::size_t c = 0; c < 3; ++c) {
    const Material channel = document.channel(static_cast<int>(c));  // the channels differ in their albedos only
    const auto found = std::find(channels.materials.begin(), channels.materials.end(), channel);
    channels.index[c] = static_cast<std::size_t>(found - channels.materials.begin());
    if (found == channels.materials.end()) channels.materials.push_back(channel);
  }
  return channels;
}

MaterialDocument grey_document(const Material& material) {
  MaterialDocument document;
  document.layer = material;
  const std::vector<StackedLayer> layers = stack_layers(material);
  for (std::size_t i = 0; i < layers.size(); ++i) {
    document.set_layer_albedo(i, {layers[i].albedo, layers[i].albedo, layers[i].albedo});
  }
  return document;
}

MaterialDocument skin_document_at_wavelength(const MaterialDocument& skin, double wavelength_nm) {
  MaterialDocument grey = grey_document(skin_material(*skin.skin, wavelength_nm, skin.layer));
  grey.name = skin.name;
  grey.description = skin.description;
  grey.model = skin.model;
  return grey;
}

}  // namespace skinlayer
