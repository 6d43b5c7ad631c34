// The unscattered BTDF through two rough interfaces (UnscatteredPath::TopThenBottom, unscattered_light.h), tabulated
// once for evaluating it at many direction pairs: its cosine series in azimuth (two_interface_series.h) on a polar
// grid, splined as the solver's tables are (core/series/layer_tables.h: the same grid map and stencil, Catmull-Rom
// taps with the (-1)^m continuation past the normal), and clamped at 0:
//
//   f_T(theta_i, theta_o, phi) ~= max(0, sum_{m < M} U_m(theta_i, theta_o) cos(m phi))                    [1/sr]
//
// unscattered_light.h's quadrature takes ~100-200 us a pair; a lookup here takes at most 16 M multiply-adds (M = 24 /
// sigma_min modes, 48 for sigma 0.5; fewer where the higher modes vanish, none far from the lobe) after a table built
// in ~0.1 s (sigma 0.5) to ~1.5 s (sigma 0.15) on 2 cores. A spline holds a lobe only a few grid steps
// wide, so the table is offered only where both interfaces' sigma >= kMinTabulatedSigma: then the lobe is > 3 grid
// steps wide at the normal (grid step 1.1 degrees there, finer toward grazing). Error against the quadrature,
// measured at points with the lobes' peaks among them (tests/core/unscattered/tabulated_two_interface_test.cpp):
// within 0.5% of the lobe's peak at theta_i <= 85 degrees, within 2% beyond.
#pragma once

#include <cstdint>
#include <vector>

#include "core/parallel_for.h"
#include "core/series/layer_tables.h"
#include "core/unscattered/unscattered_light.h"

namespace skinlayer {

inline constexpr double kMinTabulatedSigma = 0.15;
inline constexpr int kTabulatedGridSize = 129;

class TabulatedTwoInterfaceBtdf {
 public:
  // True for a TopThenBottom light whose interfaces both have sigma >= kMinTabulatedSigma.
  static bool can_tabulate(const UnscatteredLight& light);
  // Throws std::invalid_argument where can_tabulate(light) is false. The series' kernels run through parallel_for.
  explicit TabulatedTwoInterfaceBtdf(const UnscatteredLight& light, const ParallelFor& parallel_for = {});

  const UnscatteredLight& light() const { return light_; }
  int grid_size() const { return kTabulatedGridSize; }
  int modes() const { return modes_; }

  // light().btdf(theta_i, theta_o, phi) from the table (radians, graphics convention; 1/sr), at a stencil of
  // grid_size() (LayerTables::stencil) or at the angles.
  double btdf(const LayerTables::Stencil& stencil, double phi) const;
  double btdf(double theta_i, double theta_o, double phi) const;

 private:
  static constexpr int kMaxModes = 160;  // two_interface_series_modes at sigma 0.15: ceil(24 / 0.15)
  // The modes a window leaves out sum to at most this fraction of the largest sample's sum_m |U_m| (the .cpp).
  static constexpr double kNegligible = 1e-10;

  UnscatteredLight light_;
  int modes_ = 0;
  int padded_modes_ = 0;                     // modes_ rounded up to even; the extra mode is 0
  std::vector<double> coefficients_;         // U_m(theta_i, theta_o) at (i K + o) padded_modes_ + m
  std::vector<std::uint16_t> window_modes_;  // at a window's start i K + o: the modes its sum needs, even
};

}  // namespace skinlayer
