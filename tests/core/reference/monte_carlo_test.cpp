// The independent Monte Carlo reference (core/reference/monte_carlo.h) against the solver. The engine uses nothing
// of the solver; only this test brings the two together.
//
// Thresholds: |MC - solver| < 4 MC standard errors + a systematic allowance for the solver's own discretization.
//   * Albedos: 1e-3 absolute, the solver's documented accuracy for directional albedos (docs/guide/method.md,
//     "Accuracy").
//   * Binned BSDF: 1% of the value, for the solver's table splines and the averaging grid over the bin.
// Paths: 2e6 per albedo case (SE ~1e-4 to 4e-4) and 4e6 for the bins; the whole suite takes ~7 s on 2 cores.
#include "core/reference/monte_carlo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/interface_albedo.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/reference/bin_average.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

constexpr double kSigmas = 4.0;
constexpr double kAlbedoAllowance = 1e-3;
constexpr double kBsdfRelativeAllowance = 0.01;

void expect_agrees(const std::string& what, const MonteCarloEstimate& mc, double solver, double allowance) {
  const double diff = mc.value - solver;
  std::printf("  %-34s MC %.5f +- %.5f  solver %.5f  diff %+.5f = %+.2f SE (%+.2f%%)\n", what.c_str(), mc.value,
              mc.standard_error, solver, diff, mc.standard_error > 0 ? diff / mc.standard_error : 0.0,
              solver != 0.0 ? 100.0 * diff / solver : 0.0);
  EXPECT_LT(std::abs(diff), kSigmas * mc.standard_error + allowance)
      << what << ": MC " << mc.value << " +- " << mc.standard_error << ", solver " << solver;
}

MonteCarloOptions mc_options(std::uint64_t paths, std::uint64_t seed) {
  MonteCarloOptions options;
  options.paths = paths;
  options.seed = seed;
  options.threads = 2;
  return options;
}

struct AlbedoCase {
  std::string name;
  Material material;
  double theta_i_degrees;
};

std::vector<AlbedoCase> albedo_cases() {
  std::vector<AlbedoCase> cases;
  cases.push_back({"default, 30 deg", Material{}, 30.0});
  Material paper;
  paper.microfacet = MicrofacetModel::Single;
  cases.push_back({"paper default (single-scattering interfaces), 30 deg", paper, 30.0});

  Material matched;
  matched.eta = 1.0;
  matched.bottom.kind = BottomKind::Matched;
  matched.tau = optical_depth_from_transparency(0.5);
  matched.albedo = 0.9;
  matched.g = 0.5;
  cases.push_back({"eta 1, matched, T .5, Omega .9, g .5, 0 deg", matched, 0.0});

  Material lambert;
  lambert.bottom = parse_bottom("lambert:0.5");
  cases.push_back({"lambert:0.5, eta 1.4, 60 deg", lambert, 60.0});

  Material semi_infinite;
  semi_infinite.tau = optical_depth_from_transparency(0.0);
  semi_infinite.albedo = 0.9;
  semi_infinite.g = 0.0;
  cases.push_back({"semi-infinite, Omega .9, g 0, 45 deg", semi_infinite, 45.0});

  // Stacks (issue 12): an open top's beam through two layers over a rough bottom, and a rough interface between
  // layers of different g and albedo over a Lambertian base.
  Material open_stack;
  open_stack.eta = 1.0;
  open_stack.tau = 0.4;
  open_stack.albedo = 0.95;
  open_stack.g = 0.7;
  open_stack.below = {{0.8, 0.8, -0.2, std::nullopt}};
  open_stack.bottom.sigma = 0.3;
  open_stack.bottom.eta = 1.3;
  cases.push_back({"stack: open top, two layers, rough bottom, 20 deg", open_stack, 20.0});
  Material inner;
  inner.sigma = 0.3;
  inner.tau = 0.5;
  inner.albedo = 0.9;
  inner.g = 0.8;
  inner.below = {{1.0, 0.99, 0.2, LayerInterface{0.4, 0.8}}};
  inner.bottom = parse_bottom("lambert:0.5");
  cases.push_back({"stack: internal interface (eta 0.8) over lambert:0.5, 50 deg", inner, 50.0});
  return cases;
}

TEST(MonteCarlo, DirectionalAlbedosAgreeWithSolver) {
  std::uint64_t seed = 11;
  for (const AlbedoCase& c : albedo_cases()) {
    const double theta_i = degrees_to_radians(c.theta_i_degrees);
    const MonteCarloResult mc = simulate_layer(c.material, theta_i, {}, mc_options(2000000, seed++));
    const double angles[] = {theta_i};
    const DirectionalAlbedo solver = directional_albedo(c.material, angles).front();
    std::printf("%s (%llu paths, %llu truncated)\n", c.name.c_str(), static_cast<unsigned long long>(mc.paths),
                static_cast<unsigned long long>(mc.truncated_paths));
    SCOPED_TRACE(c.name);
    // The walk's light that never entered is all the top reflects, its multiply scattered part included, which the
    // solver counts with the subsurface reflectance (solver.h).
    const Vec3 toward_light = direction_from_angles(theta_i, 0.0);
    const double top_multiple =
        interface_albedo_parts(top_interface(c.material), std::span<const Vec3>(&toward_light, 1))[0].multiple.reflectance;
    expect_agrees("reflectance_surface", mc.reflectance_surface, solver.reflectance_surface + top_multiple,
                  kAlbedoAllowance);
    expect_agrees("reflectance_subsurface", mc.reflectance_subsurface, solver.reflectance_subsurface - top_multiple,
                  kAlbedoAllowance);
    expect_agrees("transmittance", mc.transmittance, solver.transmittance, kAlbedoAllowance);
    EXPECT_EQ(mc.truncated_paths, 0u);
  }
}

TEST(MonteCarlo, SameSeedGivesIdenticalResults) {
  const AngularBin bins[] = {{ExitSide::Reflected, 0.2, 0.6, 2.5, 3.8}, {ExitSide::Transmitted, 0.0, 0.5, 0.0, 6.2}};
  const MonteCarloOptions options = mc_options(20000, 42);
  const MonteCarloResult a = simulate_layer(Material{}, 0.5, bins, options);
  const MonteCarloResult b = simulate_layer(Material{}, 0.5, bins, options);
  EXPECT_EQ(a.reflectance_surface.value, b.reflectance_surface.value);
  EXPECT_EQ(a.reflectance_subsurface.value, b.reflectance_subsurface.value);
  EXPECT_EQ(a.transmittance.value, b.transmittance.value);
  EXPECT_EQ(a.transmittance.standard_error, b.transmittance.standard_error);
  ASSERT_EQ(a.bins.size(), 2u);
  for (std::size_t i = 0; i < a.bins.size(); ++i) EXPECT_EQ(a.bins[i].value, b.bins[i].value);

  MonteCarloOptions other = options;
  other.seed = 43;
  EXPECT_NE(simulate_layer(Material{}, 0.5, bins, other).transmittance.value, a.transmittance.value);
}

TEST(MonteCarlo, ProgressReachesPathCount) {
  MonteCarloOptions options = mc_options(10000, 3);
  std::uint64_t last = 0;
  bool monotone = true;
  options.progress = [&](std::uint64_t done) {
    monotone = monotone && done >= last;
    last = done;
  };
  simulate_layer(Material{}, 0.2, {}, options);
  EXPECT_TRUE(monotone);
  EXPECT_EQ(last, 10000u);
}

TEST(MonteCarlo, RejectsInvalidInput) {
  Material bad;
  bad.g = 1.5;
  EXPECT_THROW(simulate_layer(bad, 0.3, {}, {}), ParameterError);
  EXPECT_THROW(simulate_layer(Material{}, 2.0, {}, {}), ParameterError);
  EXPECT_THROW(simulate_layer(Material{}, 0.3, {}, mc_options(0, 1)), ParameterError);
}

// The solver's BSDF averaged over each bin against the walk's, within 4 standard errors and 1%.
void expect_bins_agree(const Material& material, double theta_i, const std::vector<AngularBin>& bins,
                       const MonteCarloOptions& options) {
  const MonteCarloResult mc = simulate_layer(material, theta_i, bins, options);
  const LayerTables tables = solve(material);
  for (std::size_t i = 0; i < bins.size(); ++i) {
    const AngularBin& b = bins[i];
    const double solver = layer_bsdf_bin_average(material, tables, theta_i, b);
    const bool ring = b.phi_max - b.phi_min >= 2.0 * kPi;
    char name[96];
    std::snprintf(name, sizeof name, "%s theta [%.0f,%.0f) %s %.0f", b.side == ExitSide::Reflected ? "BRDF" : "BTDF",
                  radians_to_degrees(b.theta_min), radians_to_degrees(b.theta_max), ring ? "ring" : "phi",
                  ring ? 360.0 : radians_to_degrees(0.5 * (b.phi_min + b.phi_max)));
    expect_agrees(name, mc.bins[i], solver, kBsdfRelativeAllowance * std::abs(solver));
  }
}

// The paper's default layer, in and across the plane of incidence, under either microfacet model: the paper's
// single-scattering interfaces, and the default ones, whose multiply scattered light leans forward as the photons'
// on the microsurface do.
void expect_in_plane_bins_agree(MicrofacetModel model) {
  Material material;
  material.microfacet = model;
  const double theta_i = degrees_to_radians(30.0);
  const double half_width = 0.15;  // radians of azimuth either side of the plane
  auto bin = [&](ExitSide side, double theta0_deg, double theta1_deg, double phi_centre) {
    return AngularBin{side, degrees_to_radians(theta0_deg), degrees_to_radians(theta1_deg), phi_centre - half_width,
                      phi_centre + half_width};
  };
  const std::vector<AngularBin> bins = {
      bin(ExitSide::Reflected, 20, 30, kPi),   bin(ExitSide::Reflected, 30, 40, kPi),
      bin(ExitSide::Reflected, 50, 60, kPi),   bin(ExitSide::Reflected, 20, 30, 0.0),
      bin(ExitSide::Reflected, 50, 60, 0.0),   bin(ExitSide::Transmitted, 20, 30, kPi),
      bin(ExitSide::Transmitted, 40, 50, 0.0),
  };
  expect_bins_agree(material, theta_i, bins, mc_options(4000000, 7));
}

TEST(MonteCarlo, BinnedBsdfInPlaneOfIncidenceAgreesWithSolver) { expect_in_plane_bins_agree(MicrofacetModel::Single); }

TEST(MonteCarlo, BinnedBsdfInPlaneOfIncidenceAgreesWithSolverUnderMultipleScattering) {
  expect_in_plane_bins_agree(MicrofacetModel::Multiple);
}

// The multiple-scattering interfaces (the default) against the photons that walk on the microsurface, in rings of
// exit angle (all azimuths), which mode 0 of every kernel fills.
TEST(MonteCarlo, BinnedBsdfInRingsOfExitAngleAgreesWithSolverUnderMultipleScattering) {
  const Material material;  // the default: multiple-scattering interfaces
  ASSERT_EQ(material.microfacet, MicrofacetModel::Multiple);
  const double theta_i = degrees_to_radians(30.0);
  auto ring = [](ExitSide side, double theta0_deg, double theta1_deg) {
    return AngularBin{side, degrees_to_radians(theta0_deg), degrees_to_radians(theta1_deg), 0.0, 2.0 * kPi};
  };
  const std::vector<AngularBin> bins = {
      ring(ExitSide::Reflected, 0, 20),   ring(ExitSide::Reflected, 20, 40),   ring(ExitSide::Reflected, 40, 60),
      ring(ExitSide::Reflected, 60, 80),  ring(ExitSide::Transmitted, 0, 20),  ring(ExitSide::Transmitted, 20, 40),
      ring(ExitSide::Transmitted, 40, 60), ring(ExitSide::Transmitted, 60, 80),
  };
  expect_bins_agree(material, theta_i, bins, mc_options(2000000, 9));
}

}  // namespace
}  // namespace skinlayer
