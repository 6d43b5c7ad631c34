// The whole BSDF of a solved material, for light from above, as cosine series in azimuth at every pair of polar
// angles of two lists: what a tabulated Fourier BSDF file stores (app/export/scatfun_file.h).
//
//   reflection:   f_r(theta_i, theta_o, phi) = the top's microfacet BRDF (the surface term) + brdf_subsurface
//   transmission: f_t(theta_i, theta_o, phi) = btdf                                               [1/sr]
// each as sum_k a_k cos(k phi) in the graphics convention of core/conventions.h (phi = pi forward). The parts:
//   * the scattered light: the tables' own modes (LayerTables::reflection_mode / transmission_mode, unclamped);
//   * the surface term and the unscattered lobes through one interface (core/unscattered/unscattered_light.h): sampled
// in
//     azimuth and projected by AdaptiveCosineSeries (core/series/fourier.h) until the upper half of the modes is below
//     `tolerance` of the entry's peak, so a narrow lobe gets the modes it needs and a broad one few;
//   * the unscattered lobe through two interfaces: core/unscattered/two_interface_series.h.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "core/interfaces/microfacet.h"
#include "core/parallel_for.h"
#include "core/series/layer_tables.h"

namespace skinlayer {

enum class ScatteringKind { Reflection, Transmission };

// Series for every pair (theta_i[i], theta_o[o]) and channel.
struct AzimuthalSeriesTable {
  int channels = 0;
  int rows = 0;     // theta_i
  int columns = 0;  // theta_o
  // Entry (i, o) at i * columns + o: `channels` blocks of one length each (0 where the BSDF is 0).
  std::vector<std::vector<double>> entries;

  int length(int i, int o) const { return static_cast<int>(entries[index(i, o)].size()) / channels; }
  std::span<const double> series(int i, int o, int channel) const {
    const std::vector<double>& entry = entries[index(i, o)];
    const std::size_t n = entry.size() / channels;
    return std::span<const double>(entry).subspan(channel * n, n);
  }
  std::size_t index(int i, int o) const { return static_cast<std::size_t>(i) * columns + o; }
};

struct SeriesOptions {
  double tolerance = 1e-4;  // the sampled parts' truncation (AdaptiveCosineSeries)
  int max_modes = 1024;     // their cap
  ParallelFor parallel_for;
  std::function<void()> row_done;  // called once per finished theta_i (possibly from several threads at once)
};

// top: the material's top interface (the surface term; eta = 1 has none). channels: the solved tables of each colour
// channel of one material (their unscattered light is the same: it depends on no albedo). Angles in radians in
// [0, pi/2), theta_o from the upper normal for reflection and from the lower for transmission.
AzimuthalSeriesTable bsdf_fourier_series(const RoughDielectric& top, std::span<const LayerTables> channels,
                                         ScatteringKind kind, std::span<const double> theta_i,
                                         std::span<const double> theta_o, const SeriesOptions& options = {});

}  // namespace skinlayer
