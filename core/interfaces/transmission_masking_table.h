// The height-correlated Smith masking-shadowing in transmission, G2 = B(1 + Lambda_i, 1 + Lambda_o) = B(1/g_i,
// 1/g_o) (smith_masking.h; g = G1 = 1 / (1 + Lambda) of each direction), tabulated for the slope integrals of the
// interface albedo (interface_albedo.cpp). Those evaluate it about 10^5 times a default solve, and three log-gammas
// and an exponential each (~25 ns) were most of what the multiple-scattering model added to a solve.
//
// The table holds B on a grid uniform in u = sqrt(g) in both directions, 129 x 129, built once per process from
// smith_g2_transmission. The variable is sqrt(g) and not g because B(a, 1/g_o) ~ Gamma(a) g_o^a as g_o -> 0: with a
// = 1/g_i in [1, 2) that power has an unbounded second derivative in g (a cubic in g errs by 1e-4 near g_o = 0) but
// not in u (u^(2a)). At both ends the grid is exact for the closed forms B(1, b) = g_o and B(a, 1) = g_i (quadratic
// in u). Against smith_g2_transmission: at most 2e-6 absolute anywhere, 2e-7 where both g > 0.2 (the unit test
// measures it).
//
// A row is the table interpolated at one incident g_i (Catmull-Rom along u_i), for the many outgoing directions of
// one incident direction: each evaluation is then one square root and one Catmull-Rom.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "core/series/catmull_rom.h"

namespace skinlayer {

class TransmissionMaskingRow {
 public:
  static constexpr int kNodes = 129;  // per direction, u = sqrt(G1) = 0, 1/128, ..., 1

  explicit TransmissionMaskingRow(double g1_in);  // g1_in in [0, 1]

  // G2 = B(1/g1_in, 1/g1_out), dimensionless; 0 where either G1 is 0. g1_out in [0, 1]. Inline: it is the slope
  // integrals' innermost call.
  double operator()(double g1_out) const {
    if (zero_ || g1_out <= 0.0) return 0.0;
    const double x = std::sqrt(std::min(g1_out, 1.0)) * (kNodes - 1);
    const int cell = std::min(static_cast<int>(x), kNodes - 2);
    double w[4];
    catmull_rom_weights(x - cell, w);
    const double* v = &values_[cell];  // padded nodes cell .. cell + 3 = grid nodes cell - 1 .. cell + 2
    return std::max(0.0, w[0] * v[0] + w[1] * v[1] + w[2] * v[2] + w[3] * v[3]);
  }

 private:
  std::array<double, kNodes + 2> values_{};  // B at u_o = -1/128 (a ghost), 0, ..., 1, 1 + 1/128 (a ghost)
  bool zero_ = false;
};

}  // namespace skinlayer
