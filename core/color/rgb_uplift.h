// From linear sRGB to a smooth spectrum: the sigmoid-polynomial space of Jakob & Hanika 2019 ("A Low-Dimensional
// Function Space for Efficient Spectral Upsampling", Computer Graphics Forum 38(2)), which pbrt-v4 uses for its RGB
// albedos and unbounded RGB values.
//
// A spectrum is three coefficients c and a scale s:
//   R(lambda) = s * S(c0 x^2 + c1 x + c2),   S(z) = 1/2 + z / (2 sqrt(1 + z^2)),   x = (lambda - l0) / (l1 - l0),
// with l0, l1 the first and last wavelength of the grid. S maps the line onto (0, 1), so R is smooth, positive and
// at most s. As pbrt-v4's unbounded form does, an RGB value t with largest component m gets s = 2 m and the
// coefficients that fit t / s, whose largest component is 1/2, the middle of the sigmoid's range.
//
// The fit is to the spectrum as it is written: R at the grid's wavelengths, read as linear between them and constant
// beyond the ends (core/color/spectral_color.h). Its colour is W R with W = linear_srgb_weights(grid), and the
// coefficients solve W R(c) = t / s, three equations in three unknowns, by damped Gauss-Newton (Levenberg-Marquardt).
// Jakob & Hanika minimize CIELAB distance over a 1 nm spectrum; this fit is exact in linear sRGB where it converges.
#pragma once

#include <Eigen/Core>
#include <array>
#include <span>
#include <vector>

namespace skinlayer {

struct SigmoidSpectrum {
  std::array<double, 3> coefficients{};  // c0, c1, c2 of the polynomial in the normalized wavelength x
  double scale = 0.0;                    // s; 0 for black
  double rgb_error = 0.0;                // max_c |W R - t|_c / max_c t_c of the fit (0 for black)
};

class RgbUplift {
 public:
  // wavelengths: ascending, nm, at least 3. Throws std::invalid_argument otherwise.
  explicit RgbUplift(std::span<const double> wavelengths);

  // The spectrum of linear-sRGB value t (components >= 0 and finite; std::invalid_argument otherwise). start: the
  // coefficients of a nearby colour's fit, from which the iteration converges in a step or two.
  SigmoidSpectrum fit(const std::array<double, 3>& rgb, const std::array<double, 3>* start = nullptr) const;

  // R at the grid's wavelengths.
  void values(const SigmoidSpectrum& spectrum, std::span<double> out) const;

  // Linear sRGB of values at the grid's wavelengths (W R).
  std::array<double, 3> rgb_of(std::span<const double> values) const;

  std::span<const double> wavelengths() const { return wavelengths_; }

 private:
  std::vector<double> wavelengths_;
  std::vector<double> x_;                             // normalized wavelengths in [0, 1]
  Eigen::Matrix<double, 3, Eigen::Dynamic> weights_;  // W
};

}  // namespace skinlayer
