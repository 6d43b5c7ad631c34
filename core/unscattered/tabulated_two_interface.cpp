#include "core/unscattered/tabulated_two_interface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "core/unscattered/two_interface_series.h"

namespace skinlayer {

bool TabulatedTwoInterfaceBtdf::can_tabulate(const UnscatteredLight& light) {
  return light.path() == UnscatteredPath::TopThenBottom &&
         std::min(light.top().sigma, light.bottom().sigma) >= kMinTabulatedSigma;
}

TabulatedTwoInterfaceBtdf::TabulatedTwoInterfaceBtdf(const UnscatteredLight& light, const ParallelFor& parallel_for)
    : light_(light) {
  if (!can_tabulate(light)) {
    throw std::invalid_argument("TabulatedTwoInterfaceBtdf: needs a TopThenBottom path with both sigma >= 0.15");
  }
  constexpr int k = kTabulatedGridSize;
  std::vector<double> theta(k);
  for (int n = 0; n < k; ++n) theta[n] = LayerTables::grid_angle(n, k);
  modes_ = two_interface_series_modes(light);
  if (modes_ > kMaxModes) throw std::logic_error("TabulatedTwoInterfaceBtdf: more modes than kMaxModes");
  const std::vector<Eigen::MatrixXd> series = two_interface_btdf_series(light, theta, theta, modes_, parallel_for);
  // Stored with the modes innermost, padded to an even count: a pair's 4 x 4 window is then 16 runs of contiguous
  // memory (mode-major, as LayerTables stores, a window touches a cache line per mode, K^2 doubles apart), and each
  // run is summed in lanes of (even m, odd m).
  padded_modes_ = modes_ + modes_ % 2;
  coefficients_.assign(static_cast<std::size_t>(k) * k * padded_modes_, 0.0);
  for (int m = 0; m < modes_; ++m) {
    for (int i = 0; i < k; ++i) {
      for (int o = 0; o < k; ++o)
        coefficients_[(static_cast<std::size_t>(i) * k + o) * padded_modes_ + m] = series[m](o, i);
    }
  }
  // A window's sum stops at the first even mode past which every sample's remaining modes sum, in absolute value,
  // to at most kNegligible of the largest sample's sum_m |U_m|: the modes left out change the value by at most that
  // times the absolute weights (< 1.6 for Catmull-Rom's in two axes), 0 modes far from the lobe.
  const std::size_t samples = static_cast<std::size_t>(k) * k;
  double largest = 0.0;
  for (std::size_t n = 0; n < samples; ++n) {
    double sum = 0.0;
    for (int m = 0; m < modes_; ++m) sum += std::abs(coefficients_[n * padded_modes_ + m]);
    largest = std::max(largest, sum);
  }
  std::vector<int> sample_modes(samples, 0);  // each sample's modes to sum
  for (std::size_t n = 0; n < samples; ++n) {
    double tail = 0.0;
    int m = modes_;
    while (m > 0 && tail + std::abs(coefficients_[n * padded_modes_ + m - 1]) <= kNegligible * largest) {
      tail += std::abs(coefficients_[n * padded_modes_ + m - 1]);
      --m;
    }
    sample_modes[n] = m + m % 2;
  }
  window_modes_.assign(samples, 0);
  for (int i = 0; i + 4 <= k; ++i) {
    for (int o = 0; o + 4 <= k; ++o) {
      int window = 0;
      for (int a = 0; a < 4; ++a) {
        for (int b = 0; b < 4; ++b)
          window = std::max(window, sample_modes[static_cast<std::size_t>(i + a) * k + o + b]);
      }
      window_modes_[static_cast<std::size_t>(i) * k + o] = static_cast<std::uint16_t>(window);
    }
  }
}

namespace {

using Lanes = double __attribute__((vector_size(16)));  // GCC's and Clang's vector extension: SSE2 on x86-64

Lanes load_lanes(const double* values) {
  Lanes lanes;
  std::memcpy(&lanes, values, sizeof lanes);
  return lanes;
}

}  // namespace

double TabulatedTwoInterfaceBtdf::btdf(const LayerTables::Stencil& stencil, double phi) const {
  if (stencil.grid_size != kTabulatedGridSize) {
    throw std::invalid_argument("TabulatedTwoInterfaceBtdf: a stencil of another grid size");
  }
  const std::size_t run = window_modes_[stencil.offset];
  if (run == 0) return 0.0;
  // cos(m phi) by the Chebyshev recurrence, as LayerTables sums its modes.
  std::array<double, kMaxModes> cosine;
  const double cos_phi = std::cos(phi);
  cosine[0] = 1.0;
  cosine[1] = cos_phi;  // run >= 2: it is even
  for (std::size_t m = 2; m < run; ++m) cosine[m] = 2.0 * cos_phi * cosine[m - 1] - cosine[m - 2];
  // The stencil's window starts at sample `offset` = start_i K + start_o of the K x K grid.
  const std::size_t start_i = stencil.offset / kTabulatedGridSize, start_o = stencil.offset % kTabulatedGridSize;
  const auto stride = static_cast<std::size_t>(padded_modes_);
  double sum = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    for (std::size_t b = 0; b < 4; ++b) {
      const double* values = coefficients_.data() + ((start_i + a) * kTabulatedGridSize + start_o + b) * stride;
      Lanes lanes = {0.0, 0.0};  // (sum over even m, sum over odd m) of U_m cos(m phi)
      for (std::size_t m = 0; m < run; m += 2) lanes += load_lanes(values + m) * load_lanes(cosine.data() + m);
      sum += stencil.weight_i[0][a] * stencil.weight_o[0][b] * lanes[0] +
             stencil.weight_i[1][a] * stencil.weight_o[1][b] * lanes[1];
    }
  }
  return std::max(0.0, sum);
}

double TabulatedTwoInterfaceBtdf::btdf(double theta_i, double theta_o, double phi) const {
  return btdf(LayerTables::stencil(theta_i, theta_o, kTabulatedGridSize), phi);
}

}  // namespace skinlayer
