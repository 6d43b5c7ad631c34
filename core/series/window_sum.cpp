#include "core/series/window_sum.h"

#include <cmath>
#include <cstring>

namespace skinlayer {
namespace {

// GCC's and Clang's vector extension: a pair of doubles (SSE2) and a quad (AVX2, only inside the AVX2 build below,
// so that no 32-byte vector crosses a function boundary compiled without AVX).
using Pair = double __attribute__((vector_size(16)));
using Quad = double __attribute__((vector_size(32)));

Pair load_pair(const double* values) {
  Pair lanes;
  std::memcpy(&lanes, values, sizeof lanes);
  return lanes;
}

// The window's sum in two lanes of two columns each, before the lanes are added.
Pair window_pair(const double* window, std::size_t grid_size, const double (&w_i)[4], const double (&w_o)[4]) {
  Pair left = {0.0, 0.0}, right = {0.0, 0.0};  // columns 0-1 and 2-3, summed over the rows
  for (std::size_t a = 0; a < 4; ++a) {
    const double* row = window + a * grid_size;
    left += w_i[a] * load_pair(row);
    right += w_i[a] * load_pair(row + 2);
  }
  return load_pair(w_o) * left + load_pair(w_o + 2) * right;
}

// cos(m phi) by the Chebyshev recurrence cos((m + 1) phi) = 2 cos(phi) cos(m phi) - cos((m - 1) phi); rounding grows
// ~m ulp (< 1e-13 for m < 1024).
struct CosineRecurrence {
  double cos_phi, previous, current = 1.0;  // previous = cos(-phi) at m = 0
  explicit CosineRecurrence(double phi) : cos_phi(std::cos(phi)), previous(cos_phi) {}
  void advance() {
    const double next = 2.0 * cos_phi * current - previous;
    previous = current;
    current = next;
  }
};

__attribute__((target("default"))) WindowModeSums mode_sums(const double* first, const double* second, std::size_t k,
                                                            int modes, const double (&w_i)[2][4],
                                                            const double (&w_o)[2][4], double phi) {
  CosineRecurrence cosine(phi);
  WindowModeSums sums{0.0, 0.0};
  for (int m = 0; m < modes; ++m, cosine.advance()) {
    const int odd = m % 2;
    const std::size_t shift = static_cast<std::size_t>(m) * k * k;
    const Pair a = window_pair(first + shift, k, w_i[odd], w_o[odd]);
    sums.first += (a[0] + a[1]) * cosine.current;
    if (second != nullptr) {
      const Pair b = window_pair(second + shift, k, w_i[odd], w_o[odd]);
      sums.second += (b[0] + b[1]) * cosine.current;
    }
  }
  return sums;
}

__attribute__((target("avx2,fma"))) WindowModeSums mode_sums(const double* first, const double* second, std::size_t k,
                                                             int modes, const double (&w_i)[2][4],
                                                             const double (&w_o)[2][4], double phi) {
  // Per table, the window's rows weighted by w_i and summed (a quad over the columns), times w_o and cos(m phi),
  // accumulated over the modes: the four lanes are added once, at the end. Written out without helpers, so that
  // no 32-byte vector is passed to or returned from a function (lambdas do not take this function's target).
  Quad column_weight[2];
  std::memcpy(&column_weight[0], w_o[0], sizeof(Quad));
  std::memcpy(&column_weight[1], w_o[1], sizeof(Quad));
  CosineRecurrence cosine(phi);
  Quad sum_first = {0.0, 0.0, 0.0, 0.0}, sum_second = {0.0, 0.0, 0.0, 0.0};
  for (int m = 0; m < modes; ++m, cosine.advance()) {
    const int odd = m % 2;
    const std::size_t shift = static_cast<std::size_t>(m) * k * k;
    for (int table = 0; table < (second != nullptr ? 2 : 1); ++table) {
      const double* c = (table == 0 ? first : second) + shift;
      Quad rows = {0.0, 0.0, 0.0, 0.0};
      for (std::size_t a = 0; a < 4; ++a) {
        Quad row;
        std::memcpy(&row, c + a * k, sizeof row);
        rows += w_i[odd][a] * row;
      }
      (table == 0 ? sum_first : sum_second) += cosine.current * (rows * column_weight[odd]);
    }
  }
  return {(sum_first[0] + sum_first[1]) + (sum_first[2] + sum_first[3]),
          (sum_second[0] + sum_second[1]) + (sum_second[2] + sum_second[3])};
}

}  // namespace

double window_sum(const double* window, std::size_t grid_size, const double (&w_i)[4], const double (&w_o)[4]) {
  const Pair sum = window_pair(window, grid_size, w_i, w_o);
  return sum[0] + sum[1];
}

WindowModeSums sum_window_modes(const double* first, const double* second, std::size_t grid_size, int modes,
                                const double (&w_i)[2][4], const double (&w_o)[2][4], double phi) {
  return mode_sums(first, second, grid_size, modes, w_i, w_o, phi);
}

}  // namespace skinlayer
