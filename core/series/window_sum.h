// The inner loop of LayerTables' spline (layer_tables.h): a 4 x 4 window of a K x K coefficient table weighted by
// the tensor-product Catmull-Rom taps, and its sum over the modes of a cosine series,
//
//   S = sum_{m < M} cos(m phi) sum_{a, b < 4} w_i[m % 2][a] w_o[m % 2][b] c[m K^2 + a K + b]         (units of c)
//
// (rows a of theta_i, columns b of theta_o, the window's first sample at c[0]). Most of a million-pair evaluation
// is spent here. Two builds of the mode sum are chosen at run time by the CPU: one in 4-wide AVX2 + FMA lanes (a row
// of the window a lane, the modes of each parity summed before the window is weighted), the other in 2-wide SSE2
// lanes, which any x86-64 has (each mode's window weighted, then summed). Their values differ by rounding (~1e-16 of
// sum_m |S_m|): the order of the sums differs, and FMA rounds once where the other rounds twice.
#pragma once

#include <cstddef>

namespace skinlayer {

// sum_{a, b} w_i[a] w_o[b] c[a K + b], K = grid_size.
double window_sum(const double* window, std::size_t grid_size, const double (&w_i)[4], const double (&w_o)[4]);

// S above for two tables at once, which share the window and cos(m phi); `second` may be null (its sum is 0).
struct WindowModeSums {
  double first;
  double second;
};
WindowModeSums sum_window_modes(const double* first, const double* second, std::size_t grid_size, int modes,
                                const double (&w_i)[2][4], const double (&w_o)[2][4], double phi);

}  // namespace skinlayer
