#include "core/solve/upside_down.h"

#include <cmath>
#include <utility>

namespace skinlayer {

std::optional<Material> upside_down(const Material& material) {
  if (material.bottom.kind == BottomKind::Lambert) return std::nullopt;
  const std::vector<StackedLayer> layers = stack_layers(material);  // top to bottom; layers[0] has no interface
  if (std::isinf(layers.back().tau)) return std::nullopt;

  Material flipped = material;
  flipped.below.clear();
  const bool matched = material.bottom.kind == BottomKind::Matched;
  flipped.eta = matched ? 1.0 : material.bottom_eta();
  flipped.sigma = material.bottom_sigma();
  flipped.bottom = Bottom{BottomKind::Air, material.sigma, material.eta, 0.0};

  const int count = static_cast<int>(layers.size());
  const StackedLayer& first = layers[count - 1];
  flipped.tau = first.tau;
  flipped.albedo = first.albedo;
  flipped.g = first.g;
  for (int i = count - 2; i >= 0; --i) {
    StackedLayer layer = layers[i];
    // The interface between layers i and i + 1 lies above layer i once flipped, seen from the other side.
    layer.interface.reset();
    if (const std::optional<LayerInterface>& between = layers[i + 1].interface) {
      layer.interface = LayerInterface{between->sigma, 1.0 / between->eta};
    }
    flipped.below.push_back(std::move(layer));
  }
  return flipped;
}

double index_below_over_above(const Material& material) {
  const double last = material.eta * material.internal_index_ratio();  // n_L / n_air
  return material.bottom.kind == BottomKind::Air ? last / material.bottom_eta() : last;
}

}  // namespace skinlayer
