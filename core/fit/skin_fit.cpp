#include "core/fit/skin_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/color/ciede2000.h"
#include "core/color/spectral_color.h"
#include "core/fit/bounded_least_squares.h"
#include "core/skin/skin_spectrum.h"
#include "core/solve/solve_cache.h"

namespace skinlayer {
namespace {

// The three parameters match_skin_color adjusts, and all six for spectrum fits, in skin_parameter_table()'s order.
constexpr std::string_view kColorKeys[] = {"melanin", "blood", "scattering"};
constexpr std::string_view kAllKeys[] = {"melanin", "eumelanin", "blood", "oxygenation", "epidermis", "scattering"};

template <std::size_t N>
void bounds(const std::string_view (&keys)[N], Eigen::VectorXd& lo, Eigen::VectorXd& hi) {
  lo.resize(N);
  hi.resize(N);
  for (std::size_t j = 0; j < N; ++j) {
    const ParameterInfo& info = skin_parameter_info(keys[j]);
    lo(static_cast<Eigen::Index>(j)) = info.min;
    hi(static_cast<Eigen::Index>(j)) = info.max;
  }
}

template <std::size_t N>
SkinParameters with(SkinParameters skin, const std::string_view (&keys)[N], const Eigen::VectorXd& p) {
  for (std::size_t j = 0; j < N; ++j) skin_parameter(skin, keys[j]) = p(static_cast<Eigen::Index>(j));
  return skin;
}

template <std::size_t N>
Eigen::VectorXd values(const SkinParameters& skin, const std::string_view (&keys)[N]) {
  Eigen::VectorXd p(N);
  for (std::size_t j = 0; j < N; ++j) p(static_cast<Eigen::Index>(j)) = skin_parameter(skin, keys[j]);
  return p;
}

std::vector<double> reflectance_with_cache(const SkinParameters& skin, const Material& interfaces,
                                           std::span<const double> wavelengths_nm, double theta_i, SolveCache& cache,
                                           const ParallelFor& parallel_for) {
  SolveOptions options;
  options.cache = &cache;
  options.parallel_for = parallel_for;
  const double angles[] = {theta_i};
  std::vector<double> result;
  for (const auto& rows : skin_directional_albedo(skin, interfaces, wavelengths_nm, angles, options)) {
    result.push_back(rows.front().reflectance());
  }
  return result;
}

}  // namespace

std::vector<double> skin_reflectance_spectrum(const SkinParameters& skin, const Material& interfaces,
                                              std::span<const double> wavelengths_nm, double theta_i,
                                              const ParallelFor& parallel_for) {
  SolveCache cache;
  return reflectance_with_cache(skin, interfaces, wavelengths_nm, theta_i, cache, parallel_for);
}

Eigen::Vector3d skin_normal_color(const SkinParameters& skin, const Material& interfaces,
                                  const ParallelFor& parallel_for) {
  const std::vector<double> grid = wavelength_grid(400.0, 700.0, 10.0);
  const std::vector<double> r = skin_reflectance_spectrum(skin, interfaces, grid, 0.0, parallel_for);
  return linear_srgb_weights(grid) * Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

SkinColorMatch match_skin_color(const Eigen::Vector3d& target_linear_srgb, const Material& interfaces,
                                const SkinParameters& start, const ParallelFor& parallel_for) {
  validate(start);
  const std::vector<double> grid = wavelength_grid(400.0, 700.0, 10.0);
  const Eigen::Matrix<double, 3, Eigen::Dynamic> weights = linear_srgb_weights(grid);
  const Eigen::Vector3d target_lab = linear_srgb_to_lab(target_linear_srgb.cwiseMax(0.0));
  SolveCache cache;
  const auto color_of = [&](const SkinParameters& skin) {
    const std::vector<double> r = reflectance_with_cache(skin, interfaces, grid, 0.0, cache, parallel_for);
    return Eigen::Vector3d(weights * Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size())));
  };
  // Residuals in CIELAB, so that an unreachable target ends at the perceptually nearest reachable colour.
  const auto residuals = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
    r = linear_srgb_to_lab(color_of(with(start, kColorKeys, p))) - target_lab;
  };
  Eigen::VectorXd lo, hi;
  bounds(kColorKeys, lo, hi);
  // Stop at 1e-3 in CIELAB: far below a visible difference, and below 0.5% per channel.
  constexpr double kGoodEnough = 1e-3;
  BoundedFit best = fit_in_box(residuals, 3, values(start, kColorKeys), lo, hi, 80, kGoodEnough);
  // A second start from darker, bloodier skin where the first stalls far from the target (a flat corner).
  if (best.norm() > 0.05) {
    SkinParameters other = start;
    other.melanin = 0.15;
    other.blood = 0.03;
    const BoundedFit second = fit_in_box(residuals, 3, values(other, kColorKeys), lo, hi, 60, kGoodEnough);
    const int evaluations = best.evaluations + second.evaluations;
    if (second.norm() < best.norm()) best = second;
    best.evaluations = evaluations;
  }
  SkinColorMatch match;
  match.skin = with(start, kColorKeys, best.parameters);
  match.color = color_of(match.skin);
  match.delta_e = ciede2000(target_lab, linear_srgb_to_lab(match.color));
  match.evaluations = best.evaluations + 1;
  return match;
}

SkinSpectrumFit fit_skin_spectrum(std::span<const double> wavelengths_nm, std::span<const double> reflectance,
                                  double theta_i, double from_nm, double to_nm, const Material& interfaces,
                                  const ParallelFor& parallel_for) {
  if (wavelengths_nm.size() != reflectance.size()) throw std::invalid_argument("fit_skin_spectrum: sizes differ");
  SkinSpectrumFit fit;
  for (std::size_t k = 0; k < wavelengths_nm.size(); ++k) {
    if (wavelengths_nm[k] >= from_nm && wavelengths_nm[k] <= to_nm) {
      fit.wavelengths_nm.push_back(wavelengths_nm[k]);
      fit.measured.push_back(reflectance[k]);
    }
  }
  if (fit.wavelengths_nm.size() < 6) {
    throw std::invalid_argument("the spectrum has " + std::to_string(fit.wavelengths_nm.size()) +
                                " wavelengths in the range; a fit of six parameters needs at least 6");
  }
  SolveCache cache;
  const int count = static_cast<int>(fit.wavelengths_nm.size());
  const auto residuals = [&](const Eigen::VectorXd& p, Eigen::VectorXd& r) {
    const std::vector<double> model =
        reflectance_with_cache(with(SkinParameters{}, kAllKeys, p), interfaces, fit.wavelengths_nm, theta_i, cache,
                               parallel_for);
    r.resize(count);
    for (int k = 0; k < count; ++k)
      r(k) = model[static_cast<std::size_t>(k)] - fit.measured[static_cast<std::size_t>(k)];
  };
  Eigen::VectorXd lo, hi;
  bounds(kAllKeys, lo, hi);
  const BoundedFit best = fit_in_box(residuals, count, values(SkinParameters{}, kAllKeys), lo, hi, 300);
  fit.skin = with(SkinParameters{}, kAllKeys, best.parameters);
  fit.fitted = reflectance_with_cache(fit.skin, interfaces, fit.wavelengths_nm, theta_i, cache, parallel_for);
  double sum = 0.0;
  for (int k = 0; k < count; ++k) {
    const double d = fit.fitted[static_cast<std::size_t>(k)] - fit.measured[static_cast<std::size_t>(k)];
    sum += d * d;
  }
  fit.rms = std::sqrt(sum / count);
  fit.evaluations = best.evaluations + 1;
  return fit;
}

}  // namespace skinlayer
