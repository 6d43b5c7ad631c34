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

// SKINLAYER_PORTABLE_MODE_SUM (the ThreadSanitizer build) keeps the portable sum alone: GCC's dispatcher between
// the target versions runs while the dynamic loader relocates the program, before TSan's runtime is set up, and
// TSan's instrumentation of it crashes there.
#if defined(SKINLAYER_PORTABLE_MODE_SUM)
#define SKINLAYER_DEFAULT_TARGET
#else
#define SKINLAYER_DEFAULT_TARGET __attribute__((target("default")))
#endif

// cos(m phi) by the Chebyshev recurrence cos((m + 1) phi) = 2 cos(phi) cos(m phi) - cos((m - 1) phi); rounding grows
// ~m ulp (< 1e-13 for m < 1024). Written into each build rather than shared: clang drops an inline helper that only
// a target("default") version calls.
SKINLAYER_DEFAULT_TARGET WindowModeSums mode_sums(const double* first, const double* second, std::size_t k, int modes,
                                                  const double (&w_i)[2][4], const double (&w_o)[2][4], double phi) {
  const double cos_phi = std::cos(phi);
  double current = 1.0, previous = cos_phi;  // cos(m phi), cos((m - 1) phi) at m = 0
  WindowModeSums sums{0.0, 0.0};
  for (int m = 0; m < modes; ++m) {
    const int odd = m % 2;
    const std::size_t shift = static_cast<std::size_t>(m) * k * k;
    const Pair a = window_pair(first + shift, k, w_i[odd], w_o[odd]);
    sums.first += (a[0] + a[1]) * current;
    if (second != nullptr) {
      const Pair b = window_pair(second + shift, k, w_i[odd], w_o[odd]);
      sums.second += (b[0] + b[1]) * current;
    }
    const double next = 2.0 * cos_phi * current - previous;
    previous = current;
    current = next;
  }
  return sums;
}

#if !defined(SKINLAYER_PORTABLE_MODE_SUM)
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wunused-function"  // clang 14 counts a version only the dispatcher calls as unused
#endif
__attribute__((target("avx2,fma"))) WindowModeSums mode_sums(const double* first, const double* second, std::size_t k,
                                                             int modes, const double (&w_i)[2][4],
                                                             const double (&w_o)[2][4], double phi) {
  // The weights are the same for every mode of a parity, so the modes are summed before the window is weighted:
  // per table and parity, the window's four rows (a quad over the columns each) accumulate cos(m phi) c_m over the
  // modes of that parity, and only then are weighted, by w_i per row and w_o per column. Per mode that is four
  // FMAs a table, against six (and four broadcasts) to weight each mode's window first. The even and the odd modes
  // are summed in turn, each with the Chebyshev recurrence of step 2 phi,
  //   cos((m + 2) phi) = 2 cos(2 phi) cos(m phi) - cos((m - 2) phi).
  // Written out without helpers, so that no 32-byte vector is passed to or returned from a function (lambdas do
  // not take this function's target).
  const double cos_phi = std::cos(phi), cos_2phi = 2.0 * cos_phi * cos_phi - 1.0;
  const int tables = second != nullptr ? 2 : 1;
  double sums[2] = {0.0, 0.0};
  for (int odd = 0; odd < 2; ++odd) {
    Quad rows[2][4] = {};  // [table][row]: sum over the parity's modes of cos(m phi) c_m, per column
    double current = odd ? cos_phi : 1.0, previous = odd ? cos_phi : cos_2phi;  // cos(m phi), cos((m - 2) phi)
    for (int m = odd; m < modes; m += 2) {
      const std::size_t shift = static_cast<std::size_t>(m) * k * k;
      for (int table = 0; table < tables; ++table) {
        const double* c = (table == 0 ? first : second) + shift;
        for (std::size_t a = 0; a < 4; ++a) {
          Quad row;
          std::memcpy(&row, c + a * k, sizeof row);
          rows[table][a] += current * row;
        }
      }
      const double next = 2.0 * cos_2phi * current - previous;
      previous = current;
      current = next;
    }
    Quad column_weight;
    std::memcpy(&column_weight, w_o[odd], sizeof column_weight);
    for (int table = 0; table < tables; ++table) {
      Quad weighted = w_i[odd][0] * rows[table][0];
      for (std::size_t a = 1; a < 4; ++a) weighted += w_i[odd][a] * rows[table][a];
      weighted *= column_weight;
      sums[table] += (weighted[0] + weighted[1]) + (weighted[2] + weighted[3]);
    }
  }
  return {sums[0], sums[1]};
}

#if defined(__clang__)
#pragma clang diagnostic pop
#endif
#endif  // !SKINLAYER_PORTABLE_MODE_SUM

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
