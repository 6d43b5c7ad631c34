#include "core/series/bsdf_fourier_series.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/interfaces/multiple_scattering.h"
#include "core/series/fourier.h"
#include "core/unscattered/two_interface_series.h"

namespace skinlayer {
namespace {

// Drops the trailing modes of a cosine series whose sum of magnitudes, the most they can change it at any azimuth, is
// within `tolerance` of its larger value at phi = 0 and pi.
void truncate_series(std::vector<double>& series, double tolerance) {
  double at_zero = 0.0, at_pi = 0.0;
  for (std::size_t m = 0; m < series.size(); ++m) {
    at_zero += series[m];
    at_pi += (m % 2 == 0 ? 1.0 : -1.0) * series[m];
  }
  const double floor = tolerance * std::max(std::abs(at_zero), std::abs(at_pi));
  std::size_t length = series.size();
  double tail = 0.0;
  while (length > 1 && tail + std::abs(series[length - 1]) <= floor) tail += std::abs(series[--length]);
  series.resize(length);
}

}  // namespace

AzimuthalSeriesTable bsdf_fourier_series(const RoughDielectric& top, std::span<const LayerTables> channels,
                                         ScatteringKind kind, std::span<const double> theta_i,
                                         std::span<const double> theta_o, const SeriesOptions& options) {
  if (channels.empty()) throw std::invalid_argument("bsdf_fourier_series: no channels");
  // The channels' unscattered light is one material's, each channel's weighted (a colour's mix of solves).
  const UnscatteredLight unscattered = channels.front().unscattered().scaled(1.0);
  for (const LayerTables& tables : channels) {
    if (!(tables.unscattered().scaled(1.0) == unscattered)) {
      throw std::invalid_argument("bsdf_fourier_series: the channels are not one material's");
    }
  }
  const bool reflection = kind == ScatteringKind::Reflection;
  const UnscatteredPath path = unscattered.path();
  // What is sampled in azimuth: the surface term, and the unscattered lobes of one interface (the multiply scattered
  // reflection of a rough top among them).
  const bool surface = reflection && top.eta != 1.0;
  const bool sampled_unscattered = reflection ? path == UnscatteredPath::BottomOnly
                                              : path == UnscatteredPath::BottomOnly || path == UnscatteredPath::TopOnly;
  // The multiply scattered reflection lobes: their own series, exact for them, where sampling would take hundreds of
  // modes per pair (trailing modes under the tolerance of the series' peak dropped, as AdaptiveCosineSeries does).
  const AdaptiveCosineSeries adaptive(std::max(16, options.max_modes), options.tolerance);
  std::vector<std::pair<const MultipleScatteringLobe*, MultipleScatteringReflectionSeries>> lobe_series;
  if (reflection) {
    for (const UnscatteredLight::MultipleReflection& part : unscattered.multiple_reflections(0.0, 0.0)) {
      lobe_series.emplace_back(part.lobe, MultipleScatteringReflectionSeries(*part.lobe, true, adaptive.max_modes()));
    }
  }
  std::vector<Eigen::MatrixXd> two_interface;
  if (!reflection && path == UnscatteredPath::TopThenBottom) {
    two_interface = two_interface_btdf_series(unscattered, theta_i, theta_o, two_interface_series_modes(unscattered),
                                              options.parallel_for);
  }

  AzimuthalSeriesTable table;
  table.channels = static_cast<int>(channels.size());
  table.rows = static_cast<int>(theta_i.size());
  table.columns = static_cast<int>(theta_o.size());
  table.entries.resize(static_cast<std::size_t>(table.rows) * table.columns);
  run_parallel(options.parallel_for, table.rows, [&](int i) {
    const Vec3 wi = direction_from_angles(theta_i[i], 0.0);
    const double g1_in = smith_g1_beckmann(wi.z(), top.sigma);
    for (int o = 0; o < table.columns; ++o) {
      // The surface term's series and the unscattered light's (weight 1), each sampled in azimuth on its own.
      std::vector<double> shared, lobe;
      if (surface) {
        const double g1_out = smith_g1_beckmann(std::cos(theta_o[o]), top.sigma);
        shared = adaptive([&](double phi) {
          return microfacet_brdf(top, wi, direction_from_angles(theta_o[o], phi), g1_in, g1_out);
        });
      }
      if (sampled_unscattered) {
        lobe = adaptive([&](double phi) {
          return reflection ? unscattered.brdf_single(theta_i[i], theta_o[o], phi)
                            : unscattered.btdf(theta_i[i], theta_o[o], phi);
        });
      }
      if (!lobe_series.empty()) {
        std::vector<double> multiple;
        for (const UnscatteredLight::MultipleReflection& part :
             unscattered.multiple_reflections(theta_i[i], theta_o[o])) {
          const auto found = std::ranges::find_if(lobe_series, [&](const auto& s) { return s.first == part.lobe; });
          found->second.add_to(multiple, std::cos(theta_i[i]), std::cos(theta_o[o]), part.factor);
        }
        truncate_series(multiple, options.tolerance);
        if (lobe.size() < multiple.size()) lobe.resize(multiple.size(), 0.0);
        for (std::size_t k = 0; k < multiple.size(); ++k) lobe[k] += multiple[k];
      }
      std::size_t length = std::max({shared.size(), lobe.size(), two_interface.size()});
      for (const LayerTables& tables : channels) length = std::max(length, static_cast<std::size_t>(tables.modes()));
      std::vector<double>& entry = table.entries[table.index(i, o)];
      entry.assign(length * channels.size(), 0.0);
      for (std::size_t c = 0; c < channels.size(); ++c) {
        double* series = entry.data() + c * length;
        for (std::size_t k = 0; k < shared.size(); ++k) series[k] += shared[k];
        const double weight = channels[c].unscattered().weight();
        for (std::size_t k = 0; k < lobe.size(); ++k) series[k] += weight * lobe[k];
        for (std::size_t k = 0; k < two_interface.size(); ++k) series[k] += weight * two_interface[k](o, i);
        for (int m = 0; m < channels[c].modes(); ++m) {
          series[m] += reflection ? channels[c].reflection_mode(m, theta_i[i], theta_o[o])
                                  : channels[c].transmission_mode(m, theta_i[i], theta_o[o]);
        }
      }
      // Nothing at all (an opaque material's transmission): an empty entry.
      if (std::ranges::all_of(entry, [](double a) { return a == 0.0; })) entry.clear();
    }
    if (options.row_done) options.row_done();
  });
  return table;
}

}  // namespace skinlayer
