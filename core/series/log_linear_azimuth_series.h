// A lobe known by its values at ascending azimuths 0 = phi_0 < ... < phi_K = pi (an even, 2 pi-periodic function),
// exponential between two positive values (linear in its logarithm) and linear where either is zero, and the full
// cosine series of that function in the convention of core/conventions.h:
//   f^0 = (1/pi) int_0^pi f dphi,   f^m = (2/pi) int_0^pi f cos(m phi) dphi   (m >= 1),
// in closed form, exact whatever the number of modes asked. A lobe's tail falls off exponentially in azimuth (by
// e in 9 degrees at sigma 1, grazing), which a chord between samples 13 degrees apart overestimates by a quarter;
// the exponential follows it. On a segment [a, b] where f = f_a e^(lambda (phi - a)), lambda = ln(f_b / f_a) / (b - a),
//   int_a^b f dphi = (b - a) (f_b - f_a) / ln(f_b / f_a)   (the logarithmic mean; f_a (b - a) where f_b = f_a),
//   int_a^b f cos(m phi) dphi = (lambda (f_b cos mb - f_a cos ma) + m (f_b sin mb - f_a sin ma)) / (lambda^2 + m^2),
// and where f is linear, with s = (f_b - f_a) / (b - a),
//   int_a^b f cos(m phi) dphi = f_a (sin mb - sin ma) / m + s ((b - a) sin mb / m + (cos mb - cos ma) / m^2).
// Segments where both values are below 1e-9 of the function's peak are left out.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

namespace skinlayer {

class LogLinearAzimuthSeries {
 public:
  // The azimuths in radians, ascending from 0 to pi; the first `modes` coefficients.
  LogLinearAzimuthSeries(std::span<const double> azimuths, int modes);

  int modes() const { return static_cast<int>(modes_); }
  // The coefficients of each row of `values` (functions x samples, each sample >= 0): functions x modes.
  Eigen::MatrixXd coefficients(const Eigen::MatrixXd& values) const;
  // The function itself at |phi| (folded onto [0, pi]).
  double value(std::span<const double> values, double phi) const;
  // The same in two steps, for many functions at one azimuth: where phi falls among the samples (the segment from
  // sample `first`, at fraction t of it; first + 1 past the end where phi is beyond the last), then each function.
  struct Position {
    std::size_t first;
    double t;
  };
  Position locate(double phi) const;
  double value(const double* values, const Position& at) const;

 private:
  std::vector<double> azimuths_;
  std::size_t modes_;
  std::vector<double> m_, m2_;     // the modes and their squares
  std::vector<double> cos_, sin_;  // cos(m phi_k), sin(m phi_k): [k * modes + m]
};

}  // namespace skinlayer
