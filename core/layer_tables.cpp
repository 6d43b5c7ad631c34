#include "core/layer_tables.h"

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

}  // namespace

LayerTables::LayerTables(int grid_size, int modes, std::vector<double> reflection, std::vector<double> transmission)
    : grid_size_(grid_size), modes_(modes), reflection_(std::move(reflection)), transmission_(std::move(transmission)) {
  const std::size_t expected = static_cast<std::size_t>(grid_size) * grid_size * modes;
  if (grid_size < 4 || reflection_.size() != expected || transmission_.size() != expected) {
    throw std::invalid_argument("LayerTables: table sizes do not match grid_size^2 * modes");
  }
}

double LayerTables::grid_angle(int k, int grid_size) {
  return 0.5 * kPi * std::sin(0.5 * kPi * k / (grid_size - 1));
}

double LayerTables::grid_coordinate(double theta, int grid_size) {
  const double s = std::clamp(theta / (0.5 * kPi), 0.0, 1.0);
  return std::asin(s) / (0.5 * kPi) * (grid_size - 1);
}

// Tensor-product Catmull-Rom in the grid coordinates of (theta_i, theta_o), continued past both ends by the grid's
// symmetries (see layer_tables.h).
double LayerTables::interpolate(std::span<const double> table, int m, double theta_i, double theta_o) const {
  const int k = grid_size_;
  const double parity = azimuth_parity(m);
  const auto axis = [&](double theta, int index[4], double weight[4], double sign[4]) {
    const double x = grid_coordinate(theta, k);
    const int cell = std::min(static_cast<int>(x), k - 2);
    catmull_rom_weights(x - cell, weight);
    for (int a = 0; a < 4; ++a) {
      index[a] = cell - 1 + a;
      sign[a] = 1.0;
    }
    if (index[0] < 0) {  // x = -1 is theta_1 seen across the normal
      index[0] = 1;
      sign[0] = parity;
    }
    if (index[3] > k - 1) index[3] = k - 2;  // x = K is the same direction as x = K - 2
  };
  int ii[4], io[4];
  double wi[4], wo[4], si[4], so[4];
  axis(theta_i, ii, wi, si);
  axis(theta_o, io, wo, so);
  const double* base = table.data() + static_cast<std::size_t>(m) * k * k;
  double value = 0.0;
  for (int a = 0; a < 4; ++a) {
    double row = 0.0;
    for (int b = 0; b < 4; ++b) row += wo[b] * so[b] * base[ii[a] * k + io[b]];
    value += wi[a] * si[a] * row;
  }
  return value;
}

LayerTables LayerTables::refined(int factor) const {
  if (factor < 1) throw std::invalid_argument("LayerTables::refined: factor must be at least 1");
  const int k = grid_size_;
  const int fine = factor * (k - 1) + 1;
  // On the shared map, fine sample j sits at coarse coordinate j / factor: cell j / factor, fraction (j % factor) /
  // factor. Its four taps and weights are those of interpolate(), with the same continuation past both ends.
  struct Taps {
    int index[4];
    double weight[4];
    double parity_sign[4];  // 1, or (-1)^m for the tap continued across the normal
  };
  std::vector<Taps> taps(fine);
  for (int j = 0; j < fine; ++j) {
    const int cell = std::min(j / factor, k - 2);
    Taps& t = taps[j];
    catmull_rom_weights(static_cast<double>(j - cell * factor) / factor, t.weight);
    for (int a = 0; a < 4; ++a) {
      t.index[a] = cell - 1 + a;
      t.parity_sign[a] = 0.0;
    }
    if (t.index[0] < 0) {
      t.index[0] = 1;
      t.parity_sign[0] = 1.0;
    }
    if (t.index[3] > k - 1) t.index[3] = k - 2;
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
          for (int a = 0; a < 4; ++a) {
            const double sign = taps[o].parity_sign[a] != 0.0 ? parity : 1.0;
            value += taps[o].weight[a] * sign * base[i * k + taps[o].index[a]];
          }
          rows[static_cast<std::size_t>(i) * fine + o] = value;
        }
      }
      double* out = result.data() + static_cast<std::size_t>(m) * fine * fine;
      for (int i = 0; i < fine; ++i) {
        for (int o = 0; o < fine; ++o) {
          double value = 0.0;
          for (int a = 0; a < 4; ++a) {
            const double sign = taps[i].parity_sign[a] != 0.0 ? parity : 1.0;
            value += taps[i].weight[a] * sign * rows[static_cast<std::size_t>(taps[i].index[a]) * fine + o];
          }
          out[static_cast<std::size_t>(i) * fine + o] = value;
        }
      }
    }
    return result;
  };
  return LayerTables(fine, modes_, refine(reflection_), refine(transmission_));
}

double LayerTables::sum_modes(std::span<const double> table, double theta_i, double theta_o, double phi) const {
  double value = 0.0;
  for (int m = 0; m < modes_; ++m) value += interpolate(table, m, theta_i, theta_o) * std::cos(m * phi);
  return value;
}

double LayerTables::reflection_mode(int m, double theta_i, double theta_o) const {
  return interpolate(reflection_, m, theta_i, theta_o);
}
double LayerTables::transmission_mode(int m, double theta_i, double theta_o) const {
  return interpolate(transmission_, m, theta_i, theta_o);
}
double LayerTables::brdf_subsurface(double theta_i, double theta_o, double phi) const {
  return sum_modes(reflection_, theta_i, theta_o, phi);
}
double LayerTables::btdf(double theta_i, double theta_o, double phi) const {
  return sum_modes(transmission_, theta_i, theta_o, phi);
}

}  // namespace skinlayer
