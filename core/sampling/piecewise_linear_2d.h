// A 2-D distribution on the unit square, piecewise bilinear over a regular nx x ny grid of values, optionally one per
// node of up to two parameters (blended linearly between the neighbouring nodes), with its exact sampling warp and
// that warp's inverse. It is the warp of the RGL measured-BSDF format (Dupuy & Jakob 2018, "An Adaptive
// Parameterization for Efficient Material Acquisition and Rendering"), which pbrt-v4 (PiecewiseLinear2D) and
// Mitsuba 3 (Marginal2D) read: a writer must place its sample nodes with exactly this warp, so it is written here
// from the format's definition.
//
// Per parameter slice, with d[y][x] the values (x fastest):
//   row CDFs       C[y][0] = 0,  C[y][x+1] = C[y][x] + (d[y][x] + d[y][x+1]) / 2
//   marginal CDF   M[0] = 0,     M[y+1] = M[y] + (C[y][nx-1] + C[y+1][nx-1]) / 2
// all three divided by M[ny-1] (grid units: a cell is 1 x 1). The density on [0,1]^2 is then
//   p(u) = (nx-1)(ny-1) * bilinear(d / M[ny-1], u),
// sampling inverts the marginal in y, then the row CDF (bilinearly interpolated between the two rows) in x, each
// within its cell by the quadratic that the linear density integrates to; invert() is the exact inverse.
// A parameter p is looked up as the last node <= p (clamped to the ends), with the weight (p - p_k) / (p_k+1 - p_k)
// clamped to [0, 1]; a query blends the 2^D neighbouring slices' normalized tables.
#pragma once

#include <array>
#include <span>
#include <vector>

namespace skinlayer {

class PiecewiseLinear2D {
 public:
  // values: for each combination of parameter nodes (the first parameter slowest), nx * ny values, row-major
  // (x fastest), all >= 0 with a positive integral. params: 0, 1 or 2 ascending node lists. Throws
  // std::invalid_argument for sizes that do not match, nx or ny < 2, a negative or non-finite value, or a slice that
  // integrates to 0.
  PiecewiseLinear2D(std::span<const double> values, int nx, int ny, std::vector<std::vector<double>> params = {});

  // The density at u in [0,1]^2 (per unit area of the square), at the parameters.
  double eval(std::array<double, 2> u, std::span<const double> param = {}) const;

  // The point the warp maps xi in [0,1]^2 to, and its density.
  struct Sample {
    std::array<double, 2> u;
    double pdf;
  };
  Sample sample(std::array<double, 2> xi, std::span<const double> param = {}) const;

  // The xi that sample() maps to u, and the density at u.
  Sample invert(std::array<double, 2> u, std::span<const double> param = {}) const;

  int nx() const { return nx_; }
  int ny() const { return ny_; }

 private:
  // The blend of the neighbouring slices at param: their slice indices and weights.
  struct Blend {
    std::array<std::size_t, 4> offset{};
    std::array<double, 4> weight{};
    int count = 1;
  };
  Blend blend(std::span<const double> param) const;
  // Entry i of a table blended across the slices; a slice holds per_slice entries (nx * ny, or ny for the marginal).
  static double lookup(const std::vector<double>& table, std::size_t per_slice, const Blend& b, std::size_t i);
  std::size_t cells() const { return static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_); }

  int nx_ = 0;
  int ny_ = 0;
  std::vector<std::vector<double>> params_;
  std::vector<double> data_;         // normalized values, slice after slice
  std::vector<double> conditional_;  // row CDFs, slice after slice (nx * ny per slice)
  std::vector<double> marginal_;     // marginal CDFs, slice after slice (ny per slice)
};

}  // namespace skinlayer
