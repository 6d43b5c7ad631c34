#include "core/series/layer_tables.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"

namespace skinlayer {
namespace {

// Catmull-Rom weights for the four samples around t in [0, 1] (interpolating, C1, exact for quadratics).
void catmull_rom_weights(double t, double w[4]) {
  const double t2 = t * t;
  const double t3 = t2 * t;
  w[0] = 0.5 * (-t + 2.0 * t2 - t3);
  w[1] = 0.5 * (2.0 - 5.0 * t2 + 3.0 * t3);
  w[2] = 0.5 * (t + 4.0 * t2 - 3.0 * t3);
  w[3] = 0.5 * (-t2 + t3);
}

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
}

double LayerTables::grid_angle(int k, int grid_size) { return 0.5 * kPi * std::sin(0.5 * kPi * k / (grid_size - 1)); }

double LayerTables::grid_coordinate(double theta, int grid_size) {
  const double s = std::clamp(theta / (0.5 * kPi), 0.0, 1.0);
  return std::asin(s) / (0.5 * kPi) * (grid_size - 1);
}

// The 16 taps of the tensor-product Catmull-Rom at (theta_i, theta_o) in a (K x K) table: their offsets, and their
// weights for even and for odd modes (a tap across the normal carries the mode's parity (-1)^m). Found once per
// direction pair and shared by every mode and both tables.
struct LayerTables::Stencil {
  int offset[16];
  double weight[2][16];  // [m % 2][tap]
};

LayerTables::Stencil LayerTables::stencil(double theta_i, double theta_o) const {
  const int k = grid_size_;
  const SplineTaps ti = spline_taps(grid_coordinate(theta_i, k), k);
  const SplineTaps to = spline_taps(grid_coordinate(theta_o, k), k);
  Stencil result{};
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      const int tap = 4 * a + b;
      result.offset[tap] = ti.index[a] * k + to.index[b];
      for (int odd = 0; odd < 2; ++odd) {
        const double parity = odd ? -1.0 : 1.0;
        result.weight[odd][tap] = ti.weight[a] * ti.sign(a, parity) * to.weight[b] * to.sign(b, parity);
      }
    }
  }
  return result;
}

double LayerTables::interpolate(std::span<const double> table, int m, const Stencil& taps) const {
  const double* base = table.data() + static_cast<std::size_t>(m) * grid_size_ * grid_size_;
  const double* weight = taps.weight[m % 2];
  double value = 0.0;
  for (int tap = 0; tap < 16; ++tap) value += weight[tap] * base[taps.offset[tap]];
  return value;
}

double LayerTables::interpolate(std::span<const double> table, int m, double theta_i, double theta_o) const {
  return interpolate(table, m, stencil(theta_i, theta_o));
}

LayerTables LayerTables::refined(int factor) const {
  if (factor < 1) throw std::invalid_argument("LayerTables::refined: factor must be at least 1");
  const int k = grid_size_;
  const int fine = factor * (k - 1) + 1;
  // On the shared map, fine sample j sits at coarse grid coordinate j / factor.
  std::vector<SplineTaps> taps(fine);
  for (int j = 0; j < fine; ++j) taps[j] = spline_taps(static_cast<double>(j) / factor, k);
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

// sum_m c_m cos(m phi) for both tables at once, with cos(m phi) by the Chebyshev recurrence
// cos((m + 1) phi) = 2 cos(phi) cos(m phi) - cos((m - 1) phi) (rounding grows ~m ulp: < 1e-13 for m < 1024).
// A table left out (with_... false) sums to 0.
LayerTables::ScatteredValues LayerTables::sum_modes(double theta_i, double theta_o, double phi, bool with_reflection,
                                                    bool with_transmission) const {
  const Stencil taps = stencil(theta_i, theta_o);
  const double cos_phi = std::cos(phi);
  double cos_previous = cos_phi;  // cos(-phi)
  double cos_m = 1.0;
  ScatteredValues sums{0.0, 0.0};
  for (int m = 0; m < modes_; ++m) {
    if (with_reflection) sums.reflection += interpolate(reflection_, m, taps) * cos_m;
    if (with_transmission) sums.transmission += interpolate(transmission_, m, taps) * cos_m;
    const double cos_next = 2.0 * cos_phi * cos_m - cos_previous;
    cos_previous = cos_m;
    cos_m = cos_next;
  }
  return sums;
}

LayerTables::ScatteredValues LayerTables::scattered(double theta_i, double theta_o, double phi) const {
  const ScatteredValues sums = sum_modes(theta_i, theta_o, phi, true, true);
  return {std::max(0.0, sums.reflection), std::max(0.0, sums.transmission)};
}

LayerTables::Values LayerTables::values(double theta_i, double theta_o, double phi) const {
  const ScatteredValues part = scattered(theta_i, theta_o, phi);
  return {part.reflection + unscattered_.brdf(theta_i, theta_o, phi),
          part.transmission + unscattered_.btdf(theta_i, theta_o, phi)};
}

double LayerTables::reflection_mode(int m, double theta_i, double theta_o) const {
  return interpolate(reflection_, m, theta_i, theta_o);
}
double LayerTables::transmission_mode(int m, double theta_i, double theta_o) const {
  return interpolate(transmission_, m, theta_i, theta_o);
}
double LayerTables::brdf_scattered(double theta_i, double theta_o, double phi) const {
  return std::max(0.0, sum_modes(theta_i, theta_o, phi, true, false).reflection);
}
double LayerTables::btdf_scattered(double theta_i, double theta_o, double phi) const {
  return std::max(0.0, sum_modes(theta_i, theta_o, phi, false, true).transmission);
}
double LayerTables::brdf_subsurface(double theta_i, double theta_o, double phi) const {
  return brdf_scattered(theta_i, theta_o, phi) + unscattered_.brdf(theta_i, theta_o, phi);
}
double LayerTables::btdf(double theta_i, double theta_o, double phi) const {
  return btdf_scattered(theta_i, theta_o, phi) + unscattered_.btdf(theta_i, theta_o, phi);
}

}  // namespace skinlayer
