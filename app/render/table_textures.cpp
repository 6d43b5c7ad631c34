#include "app/render/table_textures.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "table_layout.h"

namespace skinlayer {

TableTextureData make_table_textures(const ColorTables& tables) {
  TableTextureData data;
  const int grid = tables.channels[0].grid_size();
  data.size = SKINLAYER_TABLE_UPSAMPLE * (grid - 1) + 1;
  for (const LayerTables& channel : tables.channels) data.modes = std::max(data.modes, channel.modes());
  const std::size_t size = static_cast<std::size_t>(data.size);
  data.reflection.assign(static_cast<std::size_t>(data.modes) * size * size * 4, 0.0f);
  data.transmission.assign(data.reflection.size(), 0.0f);
  std::vector<double> theta(size);
  for (std::size_t j = 0; j < size; ++j) {
    const double x = static_cast<double>(j) / static_cast<double>(size - 1);
    theta[j] = 0.5 * kPi * std::sin(0.5 * kPi * x);
  }
  for (int c = 0; c < 3; ++c) {
    const LayerTables& channel = tables.channels[c];
    const int same = c > 0 && tables.material.albedo_rgb[c] == tables.material.albedo_rgb[c - 1] ? c - 1 : -1;
    for (int m = 0; m < data.modes; ++m) {
      for (std::size_t i = 0; i < size; ++i) {
        for (std::size_t o = 0; o < size; ++o) {
          const std::size_t texel = ((static_cast<std::size_t>(m) * size + i) * size + o) * 4;
          if (same >= 0) {
            data.reflection[texel + c] = data.reflection[texel + same];
            data.transmission[texel + c] = data.transmission[texel + same];
          } else if (m < channel.modes()) {
            data.reflection[texel + c] = static_cast<float>(channel.reflection_mode(m, theta[i], theta[o]));
            data.transmission[texel + c] = static_cast<float>(channel.transmission_mode(m, theta[i], theta[o]));
          }
        }
      }
    }
  }
  return data;
}

}  // namespace skinlayer
