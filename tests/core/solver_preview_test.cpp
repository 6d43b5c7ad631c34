// The solver's quick look (SolveOptions::preview) and its cancellation point (SolveOptions::cancelled): a preview
// is coarser only where the full resolution is costly, and keeps the energy; a cancellation check that never fires
// changes no bit, and one that fires abandons the solve.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <vector>

#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

// The materials whose automatic resolution is the costliest: a sharp top, a near-matched sharp top, strong forward
// scattering in a clear layer, and a sharp, near-matched bottom under a rough top.
std::vector<Material> costly_materials() {
  std::vector<Material> result(4);
  result[0].sigma = 0.05;
  result[1].sigma = 0.1;
  result[1].eta = 1.05;
  result[2].g = 0.95;
  result[2].tau = optical_depth_from_transparency(0.9);
  result[3].bottom.sigma = 0.2;
  result[3].bottom.eta = 1.05;
  return result;
}

TEST(SolverPreview, IsCoarserOnlyWhereTheFullResolutionIsCostly) {
  EXPECT_FALSE(preview_is_coarser(Material{})) << "the default material solves at full resolution at once";
  Material rough;
  rough.sigma = 1.0;
  EXPECT_FALSE(preview_is_coarser(rough));
  SolveOptions preview;
  preview.preview = true;
  for (const Material& m : costly_materials()) {
    EXPECT_TRUE(preview_is_coarser(m)) << "sigma " << m.sigma << ", eta " << m.eta << ", g " << m.g;
    const Resolution full = choose_resolution(m);
    const Resolution coarse = choose_resolution(m, preview);
    EXPECT_LE(coarse.ordinates, kPreviewResolution.ordinates);
    EXPECT_LE(coarse.max_modes, kPreviewResolution.max_modes);
    EXPECT_LE(coarse.interface_azimuths, kPreviewResolution.interface_azimuths);
    EXPECT_GE(coarse.interface_azimuths, 2 * coarse.interface_modes + 1) << "the projection must resolve its modes";
    EXPECT_LE(coarse.ordinates, full.ordinates);
    EXPECT_LE(coarse.table_size, full.table_size);
  }
}

// The tables' grid is finer only where a sharp lobe stays in them (lobe_table_size): the default material keeps 48
// nodes, the preview always does.
TEST(SolverPreview, TablesAreFinerOnlyForSharpLobesAndNeverInThePreview) {
  EXPECT_EQ(choose_resolution(Material{}).table_size, 48);
  Material rough_bottom_clear_layer;  // the bottom's reflection of unscattered light is broad at sigma 0.5
  rough_bottom_clear_layer.tau = optical_depth_from_transparency(0.9);
  rough_bottom_clear_layer.albedo = 0.0;
  EXPECT_EQ(choose_resolution(rough_bottom_clear_layer).table_size, 48);
  Material sharp_bottom = rough_bottom_clear_layer;
  sharp_bottom.bottom.sigma = 0.1;
  EXPECT_GT(choose_resolution(sharp_bottom).table_size, 48);
  Material forward;  // a sharp top lets the forward lobe of g 0.9 through a clear layer unblurred
  forward.g = 0.9;
  forward.tau = optical_depth_from_transparency(0.5);
  forward.sigma = 0.05;
  forward.bottom = parse_bottom("matched");
  EXPECT_GT(choose_resolution(forward).table_size, 48);
  SolveOptions preview;
  preview.preview = true;
  EXPECT_EQ(choose_resolution(sharp_bottom, preview).table_size, 48);
  EXPECT_TRUE(preview_is_coarser(sharp_bottom));
}

// The interface operators are matched to the accurate interface albedos at any N, so the preview's energy
// fractions stay close to the full solve's even where N falls far below 6/sigma (measured: up to 2.7%, the
// reflectance of the sigma 0.1, eta 1.05 layer at 45 degrees; most under 0.7%).
TEST(SolverPreview, KeepsTheEnergyFractionsWithinFourPercent) {
  SolveOptions preview;
  preview.preview = true;
  const std::vector<double> angles = {0.0, degrees_to_radians(45.0), degrees_to_radians(75.0)};
  for (const Material& m : costly_materials()) {
    const std::vector<DirectionalAlbedo> full = directional_albedo(m, angles);
    const std::vector<DirectionalAlbedo> quick = directional_albedo(m, angles, preview);
    for (std::size_t k = 0; k < angles.size(); ++k) {
      const auto where = ::testing::Message() << "sigma " << m.sigma << ", eta " << m.eta << ", g " << m.g
                                              << ", theta_i " << radians_to_degrees(angles[k]);
      EXPECT_NEAR(quick[k].reflectance(), full[k].reflectance(), 0.04 * full[k].reflectance()) << where;
      EXPECT_NEAR(quick[k].transmittance, full[k].transmittance, 0.04 * full[k].transmittance) << where;
    }
  }
}

TEST(SolverPreview, TablesAreFiniteAndSmallerThanTheFullSolves) {
  Material m = costly_materials()[1];
  SolveOptions preview;
  preview.preview = true;
  const LayerTables quick = solve(m, preview);
  EXPECT_LE(quick.modes(), kPreviewResolution.max_modes);
  for (const double c : quick.reflection_coefficients()) ASSERT_TRUE(std::isfinite(c));
  for (const double c : quick.transmission_coefficients()) ASSERT_TRUE(std::isfinite(c));
  // Where the BRDF is smooth (30 degrees in, 50 out, sideways) the preview is close to the full solve.
  const LayerTables full = solve(m);
  const double theta_i = degrees_to_radians(30.0), theta_o = degrees_to_radians(50.0), phi = kPi / 2;
  EXPECT_NEAR(quick.brdf_subsurface(theta_i, theta_o, phi), full.brdf_subsurface(theta_i, theta_o, phi),
              0.03 * full.brdf_subsurface(theta_i, theta_o, phi));
}

TEST(SolverCancellation, ACheckThatNeverFiresChangesNoBit) {
  Material m;
  m.sigma = 0.3;
  std::atomic<int> calls = 0;
  SolveOptions watched;
  watched.cancelled = [&calls] {
    ++calls;
    return false;
  };
  const LayerTables plain = solve(m);
  const LayerTables checked = solve(m, watched);
  EXPECT_GT(calls.load(), plain.modes()) << "asked before each mode and after the interface operators";
  ASSERT_EQ(plain.modes(), checked.modes());
  EXPECT_TRUE(std::ranges::equal(plain.reflection_coefficients(), checked.reflection_coefficients()));
  EXPECT_TRUE(std::ranges::equal(plain.transmission_coefficients(), checked.transmission_coefficients()));
}

TEST(SolverCancellation, ACheckThatFiresAbandonsTheSolve) {
  Material m;
  m.sigma = 0.3;
  std::atomic<int> calls = 0;
  SolveOptions options;
  options.cancelled = [&calls] { return ++calls >= 3; };
  EXPECT_THROW((void)solve(m, options), SolveCancelled);
  EXPECT_EQ(calls.load(), 3) << "the solve stops at the first check that fires";
  // RGB: the channels run side by side on the caller's parallel-for; the first to see the check stops the solve.
  const std::vector<double> albedos = {0.9, 0.8, 0.7};
  calls = 0;
  options.parallel_for = [](int count, const std::function<void(int)>& body) {
    for (int i = 0; i < count; ++i) body(i);
  };
  EXPECT_THROW((void)solve(m, albedos, options), SolveCancelled);
}

}  // namespace
}  // namespace skinlayer
