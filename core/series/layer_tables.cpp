#include "core/series/layer_tables.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"
#include "core/series/catmull_rom.h"
#include "core/series/window_sum.h"

namespace skinlayer {
namespace {

// The four samples, weights and signs of the spline at grid coordinate x (0 <= x <= K - 1), continued past both
// ends by the grid's symmetries (layer_tables.h): x = -1 is sample 1 seen across the normal, with the factor
// (-1)^m of mode m; x = K is the same direction as x = K - 2.
struct SplineTaps {
  int index[4];
  double weight[4];
  bool across_normal[4];

  double sign(int a, double parity) const { return across_normal[a] ? parity : 1.0; }
};

SplineTaps spline_taps(double x, int k) {
  SplineTaps taps{};
  const int cell = std::min(static_cast<int>(x), k - 2);
  catmull_rom_weights(x - cell, taps.weight);
  for (int a = 0; a < 4; ++a) taps.index[a] = cell - 1 + a;
  if (taps.index[0] < 0) {
    taps.index[0] = 1;
    taps.across_normal[0] = true;
  }
  if (taps.index[3] > k - 1) taps.index[3] = k - 2;
  return taps;
}

}  // namespace

LayerTables::LayerTables(int grid_size, int modes, std::vector<double> reflection, std::vector<double> transmission,
                         UnscatteredLight unscattered)
    : grid_size_(grid_size),
      modes_(modes),
      reflection_(std::move(reflection)),
      transmission_(std::move(transmission)),
      unscattered_(unscattered) {
  const std::size_t expected = static_cast<std::size_t>(grid_size) * grid_size * modes;
  if (grid_size < 4 || reflection_.size() != expected || transmission_.size() != expected) {
    throw std::invalid_argument("LayerTables: table sizes do not match grid_size^2 * modes");
  }
  transmission_zero_ = std::ranges::all_of(transmission_, [](double c) { return c == 0.0; });
}

double LayerTables::grid_angle(int k, int grid_size) { return 0.5 * kPi * std::sin(0.5 * kPi * k / (grid_size - 1)); }

double LayerTables::grid_coordinate(double theta, int grid_size) {
  const double s = std::clamp(theta / (0.5 * kPi), 0.0, 1.0);
  return std::asin(s) / (0.5 * kPi) * (grid_size - 1);
}

namespace {

// The window start of one axis and its folded weights for even [0] and odd [1] modes.
int fold_taps(const SplineTaps& taps, int grid_size, double (&weight)[2][4]) {
  const int start = std::clamp(taps.index[1] - 1, 0, grid_size - 4);
  for (int odd = 0; odd < 2; ++odd) {
    for (double& w : weight[odd]) w = 0.0;
    for (int a = 0; a < 4; ++a) weight[odd][taps.index[a] - start] += taps.weight[a] * taps.sign(a, odd ? -1.0 : 1.0);
  }
  return start;
}

}  // namespace

LayerTables::Stencil LayerTables::stencil(double theta_i, double theta_o, int grid_size) {
  Stencil result{};
  result.grid_size = grid_size;
  const auto fold = [grid_size](double theta, double (&weight)[2][4]) {
    return fold_taps(spline_taps(grid_coordinate(theta, grid_size), grid_size), grid_size, weight);
  };
  const int start_i = fold(theta_i, result.weight_i);
  const int start_o = fold(theta_o, result.weight_o);
  result.offset = static_cast<std::size_t>(start_i) * grid_size + start_o;
  return result;
}

double LayerTables::interpolate(std::span<const double> table, int m, const Stencil& taps) const {
  const auto k = static_cast<std::size_t>(grid_size_);
  return window_sum(table.data() + static_cast<std::size_t>(m) * k * k + taps.offset, k, taps.weight_i[m % 2],
                    taps.weight_o[m % 2]);
}

double LayerTables::interpolate(std::span<const double> table, int m, double theta_i, double theta_o) const {
  return interpolate(table, m, stencil(theta_i, theta_o, grid_size_));
}

LayerTables LayerTables::refined(int factor) const {
  if (factor < 1) throw std::invalid_argument("LayerTables::refined: factor must be at least 1");
  return resampled(factor * (grid_size_ - 1) + 1);
}

LayerTables LayerTables::resampled(int grid_size) const {
  if (grid_size < 2) throw std::invalid_argument("LayerTables::resampled: the grid needs at least 2 points");
  const int k = grid_size_;
  const int fine = grid_size;
  // On the shared map x = j / (K' - 1), sample j of the new grid sits at this grid's coordinate j (K - 1) / (K' - 1)
  // (j / factor exactly for refined: a quotient of exact integers is correctly rounded).
  std::vector<SplineTaps> taps(fine);
  for (int j = 0; j < fine; ++j) {
    taps[j] = spline_taps(static_cast<double>(j) * (k - 1) / static_cast<double>(fine - 1), k);
  }
  const auto refine = [&](std::span<const double> table) {
    std::vector<double> result(static_cast<std::size_t>(modes_) * fine * fine);
    std::vector<double> rows(static_cast<std::size_t>(k) * fine);  // coarse theta_i x fine theta_o
    for (int m = 0; m < modes_; ++m) {
      const double parity = azimuth_parity(m);
      const double* base = table.data() + static_cast<std::size_t>(m) * k * k;
      for (int i = 0; i < k; ++i) {
        for (int o = 0; o < fine; ++o) {
          double value = 0.0;
          for (int a = 0; a < 4; ++a)
            value += taps[o].weight[a] * taps[o].sign(a, parity) * base[i * k + taps[o].index[a]];
          rows[static_cast<std::size_t>(i) * fine + o] = value;
        }
      }
      double* out = result.data() + static_cast<std::size_t>(m) * fine * fine;
      for (int i = 0; i < fine; ++i) {
        for (int o = 0; o < fine; ++o) {
          double value = 0.0;
          for (int a = 0; a < 4; ++a) {
            value += taps[i].weight[a] * taps[i].sign(a, parity) *
                     rows[static_cast<std::size_t>(taps[i].index[a]) * fine + o];
          }
          out[static_cast<std::size_t>(i) * fine + o] = value;
        }
      }
    }
    return result;
  };
  return LayerTables(fine, modes_, refine(reflection_), refine(transmission_), unscattered_);
}

// sum_m c_m cos(m phi) for both tables at once (core/series/window_sum.h). A table left out (with_... false) sums
// to 0.
LayerTables::ScatteredValues LayerTables::sum_modes(const Stencil& taps, double phi, bool with_reflection,
                                                    bool with_transmission) const {
  if (taps.grid_size != grid_size_) throw std::invalid_argument("LayerTables: a stencil of another grid size");
  const double* reflection = reflection_.data() + taps.offset;
  const double* transmission = transmission_.data() + taps.offset;
  // A table of zeros sums to 0 (+0, as its sum would): a Lambertian base's transmission is not read.
  with_transmission = with_transmission && !transmission_zero_;
  if (!with_reflection && !with_transmission) return {0.0, 0.0};
  const double* first = with_reflection ? reflection : transmission;
  const double* second = with_reflection && with_transmission ? transmission : nullptr;
  const WindowModeSums sums = sum_window_modes(first, second, static_cast<std::size_t>(grid_size_), modes_,
                                               taps.weight_i, taps.weight_o, phi);
  if (!with_reflection) return {0.0, sums.first};
  return {sums.first, with_transmission ? sums.second : 0.0};
}

LayerTables::ScatteredValues LayerTables::scattered(const Stencil& taps, double phi) const {
  const ScatteredValues sums = sum_modes(taps, phi, true, true);
  return {std::max(0.0, sums.reflection), std::max(0.0, sums.transmission)};
}

double LayerTables::reflection_mode(int m, double theta_i, double theta_o) const {
  return interpolate(reflection_, m, theta_i, theta_o);
}
double LayerTables::transmission_mode(int m, double theta_i, double theta_o) const {
  return interpolate(transmission_, m, theta_i, theta_o);
}
double LayerTables::brdf_scattered(double theta_i, double theta_o, double phi) const {
  return std::max(0.0, sum_modes(stencil(theta_i, theta_o, grid_size_), phi, true, false).reflection);
}
double LayerTables::btdf_scattered(double theta_i, double theta_o, double phi) const {
  return std::max(0.0, sum_modes(stencil(theta_i, theta_o, grid_size_), phi, false, true).transmission);
}
double LayerTables::brdf_subsurface(double theta_i, double theta_o, double phi) const {
  return brdf_scattered(theta_i, theta_o, phi) + unscattered_.brdf(theta_i, theta_o, phi);
}
double LayerTables::btdf(double theta_i, double theta_o, double phi) const {
  return btdf_scattered(theta_i, theta_o, phi) + unscattered_.btdf(theta_i, theta_o, phi);
}

}  // namespace skinlayer
