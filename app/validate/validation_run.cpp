#include "app/validate/validation_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>

#include "core/conventions.h"
#include "core/interfaces/interface_albedo.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/reference/bin_average.h"
#include "core/solver.h"
#include "core/unscattered/unscattered_light.h"

namespace skinlayer::validation {
namespace {

constexpr double kThetaBandDeg = 15.0;
constexpr double kAzimuthHalfWidth = 0.25;  // radians
constexpr double kMinExpectedCounts = 25.0;
constexpr double kMaxSparseRelativeError = 0.2;
constexpr int kBinGrid = 16;
// Two values with no Monte Carlo spread (both exactly 0, say) agree when they differ by no more than rounding.
constexpr double kExactTolerance = 1e-12;

double plane_azimuth(BinPlane plane) {
  switch (plane) {
    case BinPlane::Back:
      return 0.0;
    case BinPlane::Forward:
      return kPi;
    case BinPlane::Across:
      return 0.5 * kPi;
  }
  return 0.0;
}

const char* plane_label(BinPlane plane) {
  switch (plane) {
    case BinPlane::Back:
      return "φ 0°";
    case BinPlane::Forward:
      return "φ 180°";
    case BinPlane::Across:
      return "φ 90°";
  }
  return "";
}

bool transmits(const Material& material) {
  return !std::isinf(material.total_tau()) && material.bottom.kind != BottomKind::Lambert;
}

std::string bin_name(const ValidationBin& bin) {
  char text[96];
  if (bin.peak != nullptr) {
    std::snprintf(text, sizeof text, "%s %s θo [%.1f,%.1f)", bin.side == ExitSide::Reflected ? "BRDF" : "BTDF",
                  bin.peak, bin.theta_min_deg, bin.theta_max_deg);
  } else {
    std::snprintf(text, sizeof text, "%s %s θo [%.0f,%.0f)", bin.side == ExitSide::Reflected ? "BRDF" : "BTDF",
                  plane_label(bin.plane), bin.theta_min_deg, bin.theta_max_deg);
  }
  return text;
}

constexpr double kPeakHalfWidthDeg = 2.0;

// A peak bin about the exit angle theta_deg in the forward plane (the normal's cone when theta_deg is within the
// half width of it).
ValidationBin peak_bin(ExitSide side, const char* peak, double theta_deg) {
  if (theta_deg <= kPeakHalfWidthDeg) return {side, BinPlane::Back, 0.0, kPeakHalfWidthDeg, kPi, peak};
  const double top = std::min(theta_deg + kPeakHalfWidthDeg, 89.9);
  return {side,
          BinPlane::Forward,
          top - 2.0 * kPeakHalfWidthDeg,
          top,
          degrees_to_radians(kPeakHalfWidthDeg) / std::sin(degrees_to_radians(theta_deg)),
          peak};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <typename Rows>
double worst(const Rows& rows, double (Comparison::*measure)() const, double worst_so_far) {
  for (const Comparison& c : rows) {
    if (c.verdict != Verdict::Sparse) worst_so_far = std::max(worst_so_far, std::abs((c.*measure)()));
  }
  return worst_so_far;
}

}  // namespace

std::vector<ValidationBin> validation_bins(const Material& material, double theta_i_deg) {
  std::vector<ValidationBin> bins;
  for (const ExitSide side : {ExitSide::Reflected, ExitSide::Transmitted}) {
    if (side == ExitSide::Transmitted && !transmits(material)) continue;
    for (const BinPlane plane : {BinPlane::Back, BinPlane::Forward, BinPlane::Across}) {
      for (double theta = 0.0; theta < 90.0; theta += kThetaBandDeg) {
        bins.push_back({side, plane, theta, theta + kThetaBandDeg, kAzimuthHalfWidth, nullptr});
      }
    }
  }
  if (theta_i_deg > kPeakHalfWidthDeg) bins.push_back(peak_bin(ExitSide::Reflected, "mirror", theta_i_deg));
  bins.push_back(peak_bin(ExitSide::Reflected, "normal", 0.0));
  if (transmits(material)) {
    const double straight =
        radians_to_degrees(UnscatteredLight(material).straight_through_angle(degrees_to_radians(theta_i_deg)));
    if (straight > kPeakHalfWidthDeg) bins.push_back(peak_bin(ExitSide::Transmitted, "straight through", straight));
    bins.push_back(peak_bin(ExitSide::Transmitted, "normal", 0.0));
  }
  return bins;
}

AngularBin angular_bin(const ValidationBin& bin) {
  const double phi = plane_azimuth(bin.plane);
  return {bin.side, degrees_to_radians(bin.theta_min_deg), degrees_to_radians(bin.theta_max_deg),
          phi - bin.phi_half_width, phi + bin.phi_half_width};
}

double Comparison::sigmas() const {
  const double diff = difference();
  if (standard_error > 0.0) return diff / standard_error;
  return std::abs(diff) <= kExactTolerance ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), diff);
}

double Comparison::relative() const { return solver != 0.0 ? difference() / solver : 0.0; }

bool SetResult::agrees() const {
  const auto disagrees = [](const Comparison& c) { return c.verdict == Verdict::Disagrees; };
  return std::none_of(albedos.begin(), albedos.end(), disagrees) &&
         std::none_of(bin_comparisons.begin(), bin_comparisons.end(), disagrees);
}

double SetResult::worst_sigmas() const {
  return worst(bin_comparisons, &Comparison::sigmas, worst(albedos, &Comparison::sigmas, 0.0));
}

double SetResult::worst_relative() const {
  return worst(bin_comparisons, &Comparison::relative, worst(albedos, &Comparison::relative, 0.0));
}

Verdict judge(double monte_carlo, double standard_error, double solver, double expected_counts) {
  const bool judged = expected_counts < 0.0 || expected_counts >= kMinExpectedCounts ||
                      (monte_carlo > 0.0 && standard_error <= kMaxSparseRelativeError * monte_carlo);
  if (!judged) return Verdict::Sparse;
  const Comparison c{"", monte_carlo, standard_error, solver};
  return std::abs(c.sigmas()) <= kAgreementSigmas ? Verdict::Agrees : Verdict::Disagrees;
}

double solver_bin_average(const Material& material, const LayerTables& tables, double theta_i,
                          const ValidationBin& bin) {
  // A peak bin is 4 degrees wide and the lobes in it can be under a degree: a finer grid there.
  return layer_bsdf_bin_average(material, tables, theta_i, angular_bin(bin), bin.peak ? 2 * kBinGrid : kBinGrid);
}

SetResult run_validation_set(const ValidationSet& set, const RunOptions& options) {
  SetResult result;
  result.set = set;
  const Material& material = set.material;
  const double theta_i = degrees_to_radians(set.theta_i_deg);

  const auto solver_start = std::chrono::steady_clock::now();
  const double angles[] = {theta_i};
  const DirectionalAlbedo albedo = directional_albedo(material, angles).front();
  result.tables = solve(material);
  result.bins = validation_bins(material, set.theta_i_deg);
  std::vector<double> solver_bins;
  for (const ValidationBin& bin : result.bins) {
    solver_bins.push_back(solver_bin_average(material, result.tables, theta_i, bin));
  }
  result.solver_seconds = seconds_since(solver_start);

  std::vector<AngularBin> tallies;
  for (const ValidationBin& bin : result.bins) tallies.push_back(angular_bin(bin));
  MonteCarloOptions mc_options;
  mc_options.paths = options.paths;
  mc_options.seed = options.seed;
  mc_options.threads = options.threads;
  mc_options.progress = options.progress;
  const auto mc_start = std::chrono::steady_clock::now();
  const MonteCarloResult mc = simulate_layer(material, theta_i, tallies, mc_options);
  result.monte_carlo_seconds = seconds_since(mc_start);
  result.paths = mc.paths;
  result.truncated_paths = mc.truncated_paths;

  const auto compare = [](std::string quantity, const MonteCarloEstimate& estimate, double solver,
                          double expected_counts) {
    Comparison c{std::move(quantity), estimate.value, estimate.standard_error, solver};
    c.verdict = judge(c.monte_carlo, c.standard_error, c.solver, expected_counts);
    return c;
  };
  // The walk's light that never entered is all the top reflects, its multiply scattered part included, which the
  // solver counts with the subsurface reflectance (core/solver.h).
  const Vec3 toward_light = direction_from_angles(theta_i, 0.0);
  const double top_multiple =
      interface_albedo_parts(top_interface(material), std::span<const Vec3>(&toward_light, 1)).front().multiple.reflectance;
  result.albedos.push_back(
      compare("R surface", mc.reflectance_surface, albedo.reflectance_surface + top_multiple, -1.0));
  result.albedos.push_back(
      compare("R subsurface", mc.reflectance_subsurface, albedo.reflectance_subsurface - top_multiple, -1.0));
  result.albedos.push_back(compare("T", mc.transmittance, albedo.transmittance, -1.0));
  for (std::size_t k = 0; k < result.bins.size(); ++k) {
    const double expected = static_cast<double>(mc.paths) * solver_bins[k] * tallies[k].projected_solid_angle();
    result.bin_comparisons.push_back(compare(bin_name(result.bins[k]), mc.bins[k], solver_bins[k], expected));
  }
  return result;
}

}  // namespace skinlayer::validation
