// Catmull-Rom interpolation on a uniform grid: the cubic through samples v[-1..2] around a cell, at t in [0, 1] of
// the cell from v[0] to v[1]. Interpolating, C1 across cells, exact for quadratics; its error is O(h^3) times the
// function's third derivative.
#pragma once

namespace skinlayer {

// The weights of the four samples around t.
inline void catmull_rom_weights(double t, double w[4]) {
  const double t2 = t * t;
  const double t3 = t2 * t;
  w[0] = 0.5 * (-t + 2.0 * t2 - t3);
  w[1] = 0.5 * (2.0 - 5.0 * t2 + 3.0 * t3);
  w[2] = 0.5 * (t + 4.0 * t2 - 3.0 * t3);
  w[3] = 0.5 * (-t2 + t3);
}

}  // namespace skinlayer
