#include "core/reference/point_accuracy.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/conventions.h"
#include "core/solver.h"
#include "core/unscattered/unscattered_light.h"

namespace skinlayer {
namespace {

constexpr int kConvergedOrdinates = 192;
constexpr int kConvergedTableSize = 95;  // twice the default grid's intervals
constexpr double kJudgedFraction = 1e-3;
// A quantity whose converged peak is below this [1/sr] is zero up to round-off (no scattering over a matched bottom
// has no subsurface BRDF at all: its "values" are 1e-17 residues of the subtraction of the exact unscattered part)
// and is not judged: its relative errors measure nothing.
constexpr double kRoundOffPeak = 1e-12;

void add_fine_window(std::vector<double>& angles, double centre) {
  for (int k = -60; k <= 60; ++k) {
    const double theta = centre + degrees_to_radians(0.05 * k);
    if (theta >= 0.0 && theta < 0.5 * kPi) angles.push_back(theta);
  }
}

}  // namespace

std::vector<double> judged_exit_angles(const Material& material, double theta_i) {
  std::vector<double> angles;
  for (int k = 0; k < 180; ++k) angles.push_back(degrees_to_radians(0.5 * k));
  add_fine_window(angles, 0.0);
  add_fine_window(angles, theta_i);  // the mirror direction; straight through a layer with air on both sides
  add_fine_window(angles, UnscatteredLight(material).straight_through_angle(theta_i));
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  return angles;
}

PointAccuracy point_accuracy(const Material& material, std::span<const double> incidence, const SolveOptions& options) {
  PointAccuracy result;
  const Resolution resolution = choose_resolution(material, options);
  result.ordinates = resolution.ordinates;
  result.table_size = resolution.table_size;
  const auto start = std::chrono::steady_clock::now();
  const LayerTables automatic = solve(material, options);
  result.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Material converged_material = material;
  converged_material.ordinates = std::max(kConvergedOrdinates, result.ordinates);
  SolveOptions converged_options = options;
  converged_options.table_size = std::max(kConvergedTableSize, 2 * resolution.table_size - 1);
  const LayerTables converged = solve(converged_material, converged_options);

  std::vector<PointError> samples;
  double peak_r = 0.0, peak_t = 0.0;
  for (const double theta_i : incidence) {
    for (const double theta_o : judged_exit_angles(material, theta_i)) {
      for (const double phi : {0.0, 0.5 * kPi, kPi}) {
        for (const bool transmission : {false, true}) {
          PointError p;
          p.theta_i = theta_i;
          p.theta_o = theta_o;
          p.phi = phi;
          p.transmission = transmission;
          p.value =
              transmission ? automatic.btdf(theta_i, theta_o, phi) : automatic.brdf_subsurface(theta_i, theta_o, phi);
          p.converged =
              transmission ? converged.btdf(theta_i, theta_o, phi) : converged.brdf_subsurface(theta_i, theta_o, phi);
          (transmission ? peak_t : peak_r) = std::max(transmission ? peak_t : peak_r, p.converged);
          samples.push_back(p);
        }
      }
    }
  }
  for (PointError& p : samples) {
    const double peak = p.transmission ? peak_t : peak_r;
    if (peak < kRoundOffPeak || !(p.converged > kJudgedFraction * peak)) continue;
    p.relative = std::abs(p.value - p.converged) / p.converged;
    ++result.judged;
    if (p.relative > result.worst.relative || result.judged == 1) result.worst = p;
  }
  return result;
}

}  // namespace skinlayer
