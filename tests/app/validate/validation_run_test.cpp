// The validation's comparison rules and the solver side of a bin, without running the Monte Carlo walk.
#include "app/validate/validation_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "app/validate/validation_grid.h"
#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer::validation {
namespace {

TEST(ValidationJudge, FourStandardErrorsIsTheLine) {
  EXPECT_EQ(judge(1.0, 0.01, 1.039, -1.0), Verdict::Agrees);
  EXPECT_EQ(judge(1.0, 0.01, 1.041, -1.0), Verdict::Disagrees);
  EXPECT_EQ(judge(1.0, 0.01, 0.959, -1.0), Verdict::Disagrees);
}

TEST(ValidationJudge, ZeroSpreadAgreesOnlyWithTheSameValue) {
  EXPECT_EQ(judge(0.0, 0.0, 0.0, -1.0), Verdict::Agrees);
  EXPECT_EQ(judge(0.0, 0.0, 1e-6, -1.0), Verdict::Disagrees);
  const Comparison c{"T", 0.0, 0.0, 1e-6};
  EXPECT_TRUE(std::isinf(c.sigmas()));
}

TEST(ValidationJudge, SparseBinsAreReportedNotJudgedUnlessEitherSideSeesLight) {
  // Few expected exits and a noisy estimate: sparse, whatever the values.
  EXPECT_EQ(judge(0.5, 0.3, 0.1, 10.0), Verdict::Sparse);
  // The solver expects many exits where Monte Carlo saw none: judged, and wrong.
  EXPECT_EQ(judge(0.0, 0.0, 0.1, 1000.0), Verdict::Disagrees);
  // Monte Carlo sees a well-measured signal the solver does not predict: judged, and wrong.
  EXPECT_EQ(judge(0.5, 0.05, 0.0, 0.0), Verdict::Disagrees);
}

TEST(ValidationBins, CoverBothPlanesAndAcrossOnEachSideThatLeaks) {
  const Material layer;                                      // transmits: air below
  EXPECT_EQ(validation_bins(layer, 45.0).size(), 36u + 4u);  // + mirror, normal; straight through, normal
  Material base;
  base.bottom = parse_bottom("lambert:0.5");
  EXPECT_EQ(validation_bins(base, 45.0).size(), 18u + 2u);
  Material deep;
  deep.tau = optical_depth_from_transparency(0.0);
  EXPECT_EQ(validation_bins(deep, 0.0).size(), 18u + 1u);  // at normal incidence the mirror is the normal
  for (const ValidationBin& bin : validation_bins(layer, 45.0)) {
    const AngularBin a = angular_bin(bin);
    EXPECT_LT(a.theta_min, a.theta_max);
    if (bin.peak == nullptr) {
      EXPECT_NEAR(a.phi_max - a.phi_min, 0.5, 1e-12);
    }
  }
}

// Peak bins sit on the mirror and straight-through directions, about 2 degrees either way in both angles.
TEST(ValidationBins, PeakBinsAreSmallConesOnTheSharpDirections) {
  Material matched;
  matched.bottom = parse_bottom("matched");
  int peaks = 0;
  for (const ValidationBin& bin : validation_bins(matched, 30.0)) {
    if (bin.peak == nullptr) continue;
    ++peaks;
    const AngularBin a = angular_bin(bin);
    const double centre = 0.5 * (a.theta_min + a.theta_max);
    if (std::string(bin.peak) == "normal") {
      EXPECT_EQ(a.theta_min, 0.0);
      EXPECT_NEAR(a.theta_max, degrees_to_radians(2.0), 1e-12);
      EXPECT_NEAR(a.phi_max - a.phi_min, 2.0 * kPi, 1e-12);
      continue;
    }
    const double expected = bin.side == ExitSide::Reflected ? degrees_to_radians(30.0)
                                                            : std::asin(std::sin(degrees_to_radians(30.0)) / 1.4);
    EXPECT_NEAR(centre, expected, 1e-12) << bin.peak;
    EXPECT_NEAR(a.theta_max - a.theta_min, degrees_to_radians(4.0), 1e-12);
    EXPECT_NEAR((a.phi_max - a.phi_min) * std::sin(centre), degrees_to_radians(4.0), 1e-12);
  }
  EXPECT_EQ(peaks, 4);
}

// No medium, no top interface, a Lambertian base of albedo A: the BRDF is A/pi everywhere, so every reflected bin
// averages to A/pi whatever its weight.
TEST(ValidationBins, SolverAverageOfAConstantBrdfIsTheConstant) {
  Material bare_base;
  bare_base.eta = 1.0;
  bare_base.tau = optical_depth_from_transparency(1.0);
  bare_base.bottom = parse_bottom("lambert:0.6");
  const LayerTables tables = solve(bare_base);
  for (const ValidationBin& bin : validation_bins(bare_base, 30.0)) {
    EXPECT_NEAR(solver_bin_average(bare_base, tables, 0.4, bin), 0.6 * kInvPi, 1e-6);
  }
}

TEST(ValidationGrid, CoversEveryValueTheCheckNames) {
  const std::vector<ValidationSet> grid = validation_grid();
  const auto has = [&grid](auto predicate) {
    for (const ValidationSet& s : grid) {
      if (predicate(s.material)) return true;
    }
    return false;
  };
  for (double g : {0.0, 0.5, 0.9}) EXPECT_TRUE(has([g](const Material& m) { return m.g == g; })) << g;
  for (double a : {0.5, 0.99, 1.0}) EXPECT_TRUE(has([a](const Material& m) { return m.albedo == a; })) << a;
  for (double s : {0.1, 0.5, 1.0}) EXPECT_TRUE(has([s](const Material& m) { return m.sigma == s; })) << s;
  for (double e : {1.0, 1.4, 2.0}) EXPECT_TRUE(has([e](const Material& m) { return m.eta == e; })) << e;
  for (BottomKind k : {BottomKind::Air, BottomKind::Matched, BottomKind::Lambert}) {
    EXPECT_TRUE(has([k](const Material& m) { return m.bottom.kind == k; }));
  }
  EXPECT_TRUE(has([](const Material& m) { return std::isinf(m.tau); }));
  EXPECT_TRUE(has([](const Material& m) { return m.transparency() >= 0.9; }));
  // Stacks (issue 12): two and three layers, an internal rough interface, a thin layer over a semi-infinite one.
  for (int layers : {2, 3}) EXPECT_TRUE(has([layers](const Material& m) { return m.layer_count() == layers; }));
  EXPECT_TRUE(has([](const Material& m) { return m.has_internal_interfaces(); }));
  EXPECT_TRUE(has(
      [](const Material& m) { return !m.below.empty() && std::isinf(m.below.back().tau) && m.transparency() >= 0.9; }));
  for (std::size_t k = 0; k < grid.size(); ++k) {
    EXPECT_EQ(grid[k].grid_index, k);
    EXPECT_GT(grid[k].quick_paths, 0u);
    EXPECT_GE(grid[k].paths, grid[k].quick_paths);
    EXPECT_NO_THROW(validate(grid[k].material)) << grid[k].name;
  }
}

}  // namespace
}  // namespace skinlayer::validation
