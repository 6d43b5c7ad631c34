#include "app/export/fourier_bsdf_export.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

#include "app/material/material_json.h"
#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/series/bsdf_fourier_series.h"
#include "core/solve/upside_down.h"

namespace skinlayer {

namespace {

// Y of the RGB as pbrt-v3 writes it, to its digits: its reader rebuilds G from Y, R and B with these very weights.
// The same Rec. 709 row as core/color/luminance.h (kRec709Luminance) to four digits; that one rounds the standard's.
constexpr std::array<double, 3> kLuminance = {0.212671, 0.715160, 0.072169};

struct Blocks {
  AzimuthalSeriesTable reflection, transmission;
};

// Both blocks of one side on the node angles (without the grazing node).
Blocks side_series(const ColorTables& tables, std::span<const double> theta, bool grey, SeriesOptions options) {
  const Material& layer = tables.material.layer;
  const std::span<const LayerTables> channels(tables.channels.data(), grey ? 1 : 3);
  const RoughDielectric top = top_interface(layer);
  Blocks blocks;
  blocks.reflection = bsdf_fourier_series(top, channels, ScatteringKind::Reflection, theta, theta, options);
  blocks.transmission = bsdf_fourier_series(top, channels, ScatteringKind::Transmission, theta, theta, options);
  return blocks;
}

// One entry in the file's channels and azimuth: (-1)^k a_k |mu_col|, Y R B from R G B (or the one grey channel).
std::vector<double> file_series(const AzimuthalSeriesTable& table, int i, int o, double mu_col, bool grey) {
  const int length = table.length(i, o);
  std::vector<double> series(static_cast<std::size_t>(length) * (grey ? 1 : 3), 0.0);
  for (int k = 0; k < length; ++k) {
    const double sign = azimuth_parity(k) * mu_col;
    if (grey) {
      series[k] = sign * table.series(i, o, 0)[k];
      continue;
    }
    const double r = table.series(i, o, 0)[k], g = table.series(i, o, 1)[k], b = table.series(i, o, 2)[k];
    series[k] = sign * (kLuminance[0] * r + kLuminance[1] * g + kLuminance[2] * b);
    series[length + k] = sign * r;
    series[2 * length + k] = sign * b;
  }
  return series;
}

// The truncated float entry (see the header).
std::vector<float> truncated(const std::vector<double>& series, int channels, double floor) {
  const std::size_t length = series.size() / channels;
  double total = 0.0;
  for (double a : series) total += std::abs(a);
  const double threshold = std::max(kScatfunTruncation * total / channels, floor);
  std::size_t keep = 0;
  for (std::size_t k = 0; k < length; ++k) {
    for (int c = 0; c < channels; ++c) {
      if (std::abs(series[c * length + k]) > threshold) keep = k + 1;
    }
  }
  std::vector<float> entry(keep * channels);
  for (int c = 0; c < channels; ++c) {
    for (std::size_t k = 0; k < keep; ++k) entry[c * keep + k] = static_cast<float>(series[c * length + k]);
  }
  if (!entry.empty() && !(entry[0] > 0.0f)) entry[0] = 0.0f;
  return entry;
}

}  // namespace

std::optional<ColorMaterial> upside_down(const ColorMaterial& material) {
  if (material.skin) return std::nullopt;  // its dermis is semi-infinite: no light comes from below
  std::optional<Material> layer = skinlayer::upside_down(material.layer);
  if (!layer) return std::nullopt;
  std::vector<std::array<double, 3>> albedos = {material.albedo_rgb};
  albedos.insert(albedos.end(), material.below_rgb.begin(), material.below_rgb.end());
  std::ranges::reverse(albedos);
  ColorMaterial flipped = material;
  flipped.layer = std::move(*layer);
  flipped.albedo_rgb = albedos.front();
  flipped.below_rgb.assign(albedos.begin() + 1, albedos.end());
  return flipped;
}

ScatfunTable scatfun_table(const ColorTables& above, const ColorTables* below, int nodes,
                           const std::function<void(int, int)>& progress, const ParallelFor& parallel_for) {
  if (nodes < kMinScatfunNodes || nodes > kMaxScatfunNodes) {
    throw std::invalid_argument("nodes = " + std::to_string(nodes) + " is out of range; valid range is [" +
                                std::to_string(kMinScatfunNodes) + ", " + std::to_string(kMaxScatfunNodes) + "]");
  }
  const MaterialDocument document = material_document(above.material);
  const bool grey = document.grey();
  const std::vector<double> all_angles = scatfun_node_angles(nodes);
  const std::span<const double> theta(all_angles.data(), all_angles.size() - 1);  // without mu = 0

  const int rows_per_side = 2 * static_cast<int>(theta.size());
  const int total = below ? 2 * rows_per_side : rows_per_side;
  std::atomic<int> done = 0;
  SeriesOptions options;
  options.parallel_for = parallel_for;
  options.row_done = [&] {
    const int now = ++done;
    if (progress) progress(now, total);
  };
  const Blocks from_above = side_series(above, theta, grey, options);
  std::optional<Blocks> from_below;
  if (below) from_below = side_series(*below, theta, grey, options);

  ScatfunTable table;
  table.mu = scatfun_mu_grid(nodes);
  table.channels = grey ? 1 : 3;
  const Material& layer = above.material.layer;
  table.eta = static_cast<float>(index_below_over_above(layer));
  table.alpha = {static_cast<float>(layer.sigma),
                 static_cast<float>(layer.bottom.kind == BottomKind::Air ? layer.bottom_sigma() : 0.0)};
  table.metadata = material_json_text(document);

  // Node p: the upward half (mu < 0) for p < nodes, theta index p; the downward half for p >= nodes, theta index
  // 2 nodes - 1 - p; theta index nodes - 1 is the doubled 0.
  const auto node = [nodes](int p) { return std::pair<bool, int>{p >= nodes, p < nodes ? p : 2 * nodes - 1 - p}; };
  const std::size_t n = table.mu.size();
  std::vector<std::vector<double>> series(n * n);
  double largest = 0.0;
  for (std::size_t row = 0; row < n; ++row) {
    const auto [row_down, i] = node(static_cast<int>(row));
    if (i == nodes - 1) continue;
    const Blocks* side = row_down ? &from_above : (from_below ? &*from_below : nullptr);
    if (!side) continue;
    for (std::size_t col = 0; col < n; ++col) {
      const auto [col_down, o] = node(static_cast<int>(col));
      if (o == nodes - 1) continue;
      // Light going down (from above) is reflected up and transmitted down; light going up, the reverse.
      const bool transmitted = col_down == row_down;
      const AzimuthalSeriesTable& block = transmitted ? side->transmission : side->reflection;
      std::vector<double>& entry = series[row * n + col];
      entry = file_series(block, i, o, std::cos(all_angles[o]), grey);
      for (double a : entry) largest = std::max(largest, std::abs(a));
    }
  }
  table.entries.resize(n * n);
  for (std::size_t e = 0; e < n * n; ++e) table.entries[e] = truncated(series[e], table.channels, 1e-7 * largest);
  return table;
}

}  // namespace skinlayer
