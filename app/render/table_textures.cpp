#include "app/render/table_textures.h"

#include <algorithm>
#include <array>
#include <span>

#include "app/process/parallel_for.h"
#include "table_layout.h"

namespace skinlayer {

TableTextureData make_table_textures(const ColorTables& tables) {
  TableTextureData data;
  for (const LayerTables& channel : tables.channels) data.modes = std::max(data.modes, channel.modes());
  // Channels with equal albedos (every layer's) share one refined table; a skin's channels are its spectrum's
  // weighted sums, each its own.
  std::vector<int> distinct_channels;
  std::array<std::size_t, 3> source{};
  const MaterialDocument document = material_document(tables.material);
  for (int c = 0; c < 3; ++c) {
    const bool same = c > 0 && !document.skin && document.channel(c) == document.channel(c - 1);
    if (!same) distinct_channels.push_back(c);
    source[c] = distinct_channels.size() - 1;
  }
  // Each channel is solved on the grid it needs (solve_color); the textures share the finest of them, refined.
  int grid_size = 0;
  for (const LayerTables& channel : tables.channels) grid_size = std::max(grid_size, channel.grid_size());
  const int texels = SKINLAYER_TABLE_UPSAMPLE * (grid_size - 1) + 1;
  std::vector<LayerTables> distinct(distinct_channels.size());
  parallel_for_threads(static_cast<int>(distinct.size()), [&](int k) {
    const auto index = static_cast<std::size_t>(k);
    distinct[index] = tables.channels[distinct_channels[index]].resampled(texels);
  });
  data.size = distinct.front().grid_size();
  data.unscattered = tables.channels[0].unscattered();  // the same for every channel: no albedo in it
  const std::size_t plane = static_cast<std::size_t>(data.size) * data.size;
  data.reflection.assign(static_cast<std::size_t>(data.modes) * plane * 4, 0.0f);
  data.transmission.assign(data.reflection.size(), 0.0f);
  for (int c = 0; c < 3; ++c) {
    const LayerTables& refined = distinct[source[c]];
    const std::span<const double> reflection = refined.reflection_coefficients();
    const std::span<const double> transmission = refined.transmission_coefficients();
    const std::size_t values = static_cast<std::size_t>(refined.modes()) * plane;  // [mode][row][column]
    for (std::size_t v = 0; v < values; ++v) {
      data.reflection[4 * v + c] = static_cast<float>(reflection[v]);
      data.transmission[4 * v + c] = static_cast<float>(transmission[v]);
    }
  }
  return data;
}

}  // namespace skinlayer
