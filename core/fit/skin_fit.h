// "Pick the colour, get the parameters" and fits to measured spectra (issue 25), on the spectral skin
// (core/skin/skin_spectrum.h):
//   match_skin_color: melanin, blood and scattering (the others as given) such that the skin's colour at normal
//     incidence under a white furnace, the reflectance (surface and subsurface) at 0 degrees weighted to linear sRGB
//     under D65, is the target; the nearest reachable colour otherwise, nearest in CIELAB.
//   fit_skin_spectrum: all six parameters to a measured directional-hemispherical reflectance spectrum at one
//     incidence angle, least squares in reflectance at the measurement's wavelengths within a range.
// Both solve the skin at every wavelength of their grid per trial (mode 0 only: fluxes, cheap) with one warm cache.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/material.h"
#include "core/parallel_for.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer {

// The skin's reflectance at theta_i (radians) at each wavelength.
std::vector<double> skin_reflectance_spectrum(const SkinParameters& skin, const Material& interfaces,
                                              std::span<const double> wavelengths_nm, double theta_i,
                                              const ParallelFor& parallel_for = {});

// The skin's linear sRGB at normal incidence (400-700 nm in 10 nm steps, core/color/spectral_color.h).
Eigen::Vector3d skin_normal_color(const SkinParameters& skin, const Material& interfaces,
                                  const ParallelFor& parallel_for = {});

struct SkinColorMatch {
  SkinParameters skin;
  Eigen::Vector3d color;  // what it gives, linear sRGB
  double delta_e = 0.0;   // CIEDE2000 between the target and `color`
  int evaluations = 0;
};
// start: the parameters that stay (eumelanin, oxygenation, epidermis) and the first guess for the three adjusted.
SkinColorMatch match_skin_color(const Eigen::Vector3d& target_linear_srgb, const Material& interfaces,
                                const SkinParameters& start = {}, const ParallelFor& parallel_for = {});

struct SkinSpectrumFit {
  SkinParameters skin;
  std::vector<double> wavelengths_nm;  // the measured wavelengths inside the range
  std::vector<double> measured, fitted;
  double rms = 0.0;  // root mean square of fitted - measured
  int evaluations = 0;
};
// measured: (wavelength_nm, reflectance) pairs, any grid, ascending. Only wavelengths in [from_nm, to_nm] count.
SkinSpectrumFit fit_skin_spectrum(std::span<const double> wavelengths_nm, std::span<const double> reflectance,
                                  double theta_i, double from_nm, double to_nm, const Material& interfaces,
                                  const ParallelFor& parallel_for = {});

}  // namespace skinlayer
