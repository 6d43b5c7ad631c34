#include "app/preview/layer_stack.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace skinlayer {

std::vector<EditableLayer> editable_layers(const ColorMaterial& material) {
  const MaterialDocument document = material_document(material);
  const std::vector<StackedLayer> layers = stack_layers(material.layer);
  std::vector<EditableLayer> result;
  for (std::size_t i = 0; i < layers.size(); ++i) result.push_back({layers[i], document.layer_albedo(i)});
  return result;
}

void set_layers(ColorMaterial& material, std::vector<EditableLayer> layers) {
  if (layers.empty()) return;
  layers.front().layer.interface.reset();
  Material& m = material.layer;
  m.tau = layers.front().layer.tau;
  m.g = layers.front().layer.g;
  m.albedo = layers.front().albedo[0];
  material.albedo_rgb = layers.front().albedo;
  m.below.clear();
  material.below_rgb.clear();
  for (std::size_t i = 1; i < layers.size(); ++i) {
    StackedLayer layer = layers[i].layer;
    layer.albedo = layers[i].albedo[0];
    m.below.push_back(layer);
    material.below_rgb.push_back(layers[i].albedo);
  }
}

void add_layer(ColorMaterial& material) {
  std::vector<EditableLayer> layers = editable_layers(material);
  EditableLayer copy = layers.back();
  copy.layer.interface.reset();
  if (std::isinf(layers.back().layer.tau)) {
    copy.layer.tau = kUnburiedDepth;
    layers.insert(layers.end() - 1, copy);
  } else {
    layers.push_back(copy);
  }
  set_layers(material, std::move(layers));
  material.model = SubsurfaceModel::Stam;  // the comparison models describe one layer
}

void remove_layer(ColorMaterial& material, std::size_t i) {
  std::vector<EditableLayer> layers = editable_layers(material);
  if (layers.size() < 2 || i >= layers.size()) return;
  layers.erase(layers.begin() + static_cast<std::ptrdiff_t>(i));
  set_layers(material, std::move(layers));
}

bool can_move(const ColorMaterial& material, std::size_t i, int offset) {
  const std::vector<EditableLayer> layers = editable_layers(material);
  const std::ptrdiff_t j = static_cast<std::ptrdiff_t>(i) + offset;
  if (i >= layers.size() || j < 0 || j >= static_cast<std::ptrdiff_t>(layers.size()) || offset == 0) return false;
  // The lower of the two moves up, above another layer: it must be finite.
  const std::size_t lower = std::max(i, static_cast<std::size_t>(j));
  return !std::isinf(layers[lower].layer.tau);
}

void move_layer(ColorMaterial& material, std::size_t i, int offset) {
  if (!can_move(material, i, offset)) return;
  std::vector<EditableLayer> layers = editable_layers(material);
  std::swap(layers[i], layers[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + offset)]);
  set_layers(material, std::move(layers));
}

}  // namespace skinlayer
