// The solver's result: the subsurface BRDF and the layer BTDF as Fourier series in azimuth whose coefficients are
// tabulated on a uniform polar-angle grid and interpolated with cubic (Catmull-Rom) splines.
//
//   f_sub(theta_i, theta_o, phi) = sum_{m < M} S_m(theta_i, theta_o) cos(m phi)        [1/sr]
//   f_T  (theta_i, theta_o, phi) = sum_{m < M} B_m(theta_i, theta_o) cos(m phi)        [1/sr]
//
// Angles follow core/conventions.h (graphics convention; the (-1)^m parity is already folded into S_m and B_m).
// Grid, the same for theta_i and theta_o: uniform in x in [0, 1] with theta = (pi/2) sin(pi x / 2), i.e.
//   theta_k = (pi/2) sin((pi/2) k / (K - 1)),  k = 0..K-1,
// nearly uniform in theta near the normal and ever finer toward grazing, where thin layers vary fastest
// (e^{-tau/mu}). The map is odd about x = 0 and even about x = 1, so the spline continues exactly past both ends:
// S_m(-theta) = (-1)^m S_m(theta), and x = 1 + d is the same direction as x = 1 - d.
// Storage: coefficient (m, i, o) at index (m * K + i) * K + o.
//
// The light that crosses the slab unscattered through sharp interfaces makes lobes narrower than the grid. The
// solver leaves it out of the coefficients and stores it as an UnscatteredLight (core/unscattered/unscattered_light.h),
// which brdf_subsurface() and btdf() add at the requested directions: the coefficients are the scattered light alone.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/unscattered/unscattered_light.h"

namespace skinlayer {

class LayerTables {
 public:
  LayerTables() = default;
  LayerTables(int grid_size, int modes, std::vector<double> reflection, std::vector<double> transmission,
              UnscatteredLight unscattered = {});

  int grid_size() const { return grid_size_; }
  int modes() const { return modes_; }

  // theta_k of the grid above (radians), and its inverse: the continuous grid coordinate x (K - 1) of theta.
  static double grid_angle(int k, int grid_size);
  static double grid_coordinate(double theta, int grid_size);

  std::span<const double> reflection_coefficients() const { return reflection_; }
  std::span<const double> transmission_coefficients() const { return transmission_; }
  const UnscatteredLight& unscattered() const { return unscattered_; }

  // Subsurface BRDF and layer BTDF in 1/sr at arbitrary angles (radians, graphics convention): the unscattered part
  // (exact) plus the scattered part (the Fourier sum of the splined coefficients) clamped at 0: the
  // grid values are >= 0, but beside a lobe narrower than a grid step (a sharp refraction lobe, sigma 0.05 with no
  // medium) the Catmull-Rom spline undershoots between them, by up to ~6% of the lobe's peak. shaders/tables.glsl
  // clamps alike. The per-mode coefficients (reflection_mode, transmission_mode) are signed and not clamped.
  double brdf_subsurface(double theta_i, double theta_o, double phi) const;
  double btdf(double theta_i, double theta_o, double phi) const;
  // The scattered parts alone (the clamped Fourier sums of the coefficients), without unscattered().
  double brdf_scattered(double theta_i, double theta_o, double phi) const;
  double btdf_scattered(double theta_i, double theta_o, double phi) const;
  // The two at once, for many direction pairs: scattered(stencil, phi) below.
  struct ScatteredValues {
    double reflection;    // brdf_scattered  [1/sr]
    double transmission;  // btdf_scattered  [1/sr]
  };

  // The spline's taps at one direction pair on a grid of grid_size angles: the tensor-product Catmull-Rom as
  // weights on a 4 x 4 window of contiguous samples (rows start_i.., columns start_o..). Each axis' taps are folded
  // onto its window: past the normal (cell 0) tap -1 is sample 1 with the mode's parity (-1)^m, so the window's
  // weights there differ between even and odd modes; past grazing (cell K - 2) tap K is sample K - 2. Found once
  // per pair, it serves every mode and both tables of every LayerTables of that grid size (a colour's channels).
  struct Stencil {
    int grid_size;
    std::size_t offset;     // start_i K + start_o
    double weight_i[2][4];  // [m % 2][row]
    double weight_o[2][4];  // [m % 2][column]
  };
  static Stencil stencil(double theta_i, double theta_o, int grid_size);
  // brdf_scattered and btdf_scattered at the stencil's pair, sharing its taps and cos(m phi) (the stencil of this
  // grid size; std::invalid_argument otherwise).
  ScatteredValues scattered(const Stencil& stencil, double phi) const;

  // The same tables on a grid `factor` times finer (the unscattered part is carried unchanged), K' = factor (K - 1) + 1
  // points on the same map: every value is this table's spline at the finer grid angle, so a bilinear lookup of the
  // result approximates the spline to O((h/factor)^2). Built separably: one 1-D Catmull-Rom pass per axis.
  LayerTables refined(int factor) const;
  // The same tables on a grid of grid_size points on the same map, coarser or finer: every value is this table's
  // spline at the new grid's angle (refined(f) is resampled(f (K - 1) + 1)). A colour's channels solved on grids of
  // their own share one grid so (the previewer's textures, app/render/table_textures.h).
  LayerTables resampled(int grid_size) const;

  // The m-th azimuthal coefficient, spline-interpolated.
  double reflection_mode(int m, double theta_i, double theta_o) const;
  double transmission_mode(int m, double theta_i, double theta_o) const;

 private:
  double interpolate(std::span<const double> table, int m, const Stencil& taps) const;
  double interpolate(std::span<const double> table, int m, double theta_i, double theta_o) const;
  ScatteredValues sum_modes(const Stencil& taps, double phi, bool with_reflection, bool with_transmission) const;

  int grid_size_ = 0;
  int modes_ = 0;
  std::vector<double> reflection_;
  std::vector<double> transmission_;
  bool transmission_zero_ = true;  // every transmission coefficient is 0 (a Lambertian base): its sum is skipped
  UnscatteredLight unscattered_;
};

}  // namespace skinlayer
