// The inner loop of LayerTables' spline (layer_tables.h): a 4 x 4 window of a K x K coefficient table weighted by
// the tensor-product Catmull-Rom taps (rows a of theta_i, columns b of theta_o, the window's first sample at c[0]):
//
//   sum_{a, b < 4} w_i[a] w_o[b] c[a K + b]                                                          (units of c)
//
// Most of a million-pair evaluation is spent here.
#pragma once

#include <cstddef>

namespace skinlayer {

// The sum above, K = grid_size.
double window_sum(const double* window, std::size_t grid_size, const double (&w_i)[4], const double (&w_o)[4]);

}  // namespace skinlayer
