// solve_color's channels are each the solve of that channel alone: for every preset, each channel of the RGB
// tables that the previewer, render and export show equals its own grey solve (the same grid, modes and
// coefficients), and every channel, a skin's included, evaluates to what `eval` gives at the same directions
// (solve_document + evaluate), to the tolerance eval's own RGB test holds each channel to: 1e-9 relative.
#include "app/solution/material_solve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/material/presets.h"
#include "app/process/parallel_for.h"
#include "app/solution/solved_document.h"
#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

constexpr double kRelativeTolerance = 1e-9;

// |a - b| within the relative tolerance of the larger of the two, or of `scale` (the table's largest value) where
// both are round-off next to it.
::testing::AssertionResult close(double a, double b, double scale) {
  const double bound = kRelativeTolerance * std::max({std::abs(a), std::abs(b), 1e-6 * scale});
  if (std::abs(a - b) <= bound) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b << " (difference " << std::abs(a - b) << ", bound " << bound
                                       << ")";
}

double largest_magnitude(std::span<const double> values) {
  double largest = 0.0;
  for (const double v : values) largest = std::max(largest, std::abs(v));
  return largest;
}

void expect_same_coefficients(std::span<const double> rgb, std::span<const double> grey, const std::string& what) {
  ASSERT_EQ(rgb.size(), grey.size()) << what;
  const double scale = largest_magnitude(grey);
  std::size_t failures = 0;
  for (std::size_t k = 0; k < rgb.size() && failures < 5; ++k) {
    const ::testing::AssertionResult result = close(rgb[k], grey[k], scale);
    if (!result) {
      ADD_FAILURE() << what << " coefficient " << k << ": " << result.message();
      ++failures;
    }
  }
}

// The presets of layers (not a skin, whose channels are spectral mixes: the next test holds them to eval).
std::vector<std::string> layered_presets() {
  std::vector<std::string> names;
  for (const std::string& name : preset_names()) {
    if (!preset_material(name).skin) names.push_back(name);
  }
  return names;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& param) {
  std::string name = param.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

class EveryLayeredPreset : public ::testing::TestWithParam<std::string> {};
class EveryPreset : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryLayeredPreset, EachRgbChannelIsItsOwnGreySolve) {
  const MaterialDocument document = preset_material(GetParam());
  SolveOptions options;
  options.parallel_for = parallel_for_threads;
  const ColorTables tables = solve_color(color_material(document), 0.0, options);
  for (int c = 0; c < 3; ++c) {
    const Material channel = document.channel(c);
    const LayerTables grey = solve(channel, options);
    const std::string what = GetParam() + " channel " + std::to_string(c);
    EXPECT_EQ(tables.channels[c].grid_size(), grey.grid_size()) << what;
    EXPECT_EQ(tables.channels[c].modes(), grey.modes()) << what;
    expect_same_coefficients(tables.channels[c].reflection_coefficients(), grey.reflection_coefficients(),
                             what + " reflection");
    expect_same_coefficients(tables.channels[c].transmission_coefficients(), grey.transmission_coefficients(),
                             what + " transmission");
    const DirectionalAlbedo albedo = directional_albedo(channel, std::vector<double>{0.0}, options).front();
    EXPECT_TRUE(close(tables.albedo[c].reflectance_subsurface, albedo.reflectance_subsurface, 1.0)) << what;
    EXPECT_TRUE(close(tables.albedo[c].transmittance, albedo.transmittance, 1.0)) << what;
  }
}

// The directions eval is asked at: near the normal, the lobes' flanks, grazing, forward and backward.
constexpr double kPairs[][3] = {{0, 0, 0},     {30, 25, 180}, {60, 70, 90}, {80, 10, 0},
                                {45, 45, 180}, {20, 60, 135}, {5, 85, 180}, {70, 70, 0}};

TEST_P(EveryPreset, EachChannelEvaluatesAsEvalDoes) {
  const MaterialDocument document = preset_material(GetParam());
  SolveOptions options;
  options.parallel_for = parallel_for_threads;
  const ColorTables tables = solve_color(color_material(document), 0.0, options);
  const SolvedDocument solved = solve_document(document, SubsurfaceModel::Stam, parallel_for_threads);
  for (const auto& pair : kPairs) {
    const double theta_i = degrees_to_radians(pair[0]), theta_o = degrees_to_radians(pair[1]);
    const double phi = degrees_to_radians(pair[2]);
    const BsdfPoint point = evaluate(solved, theta_i, theta_o, phi);
    for (int c = 0; c < 3; ++c) {
      const std::string what = GetParam() + " channel " + std::to_string(c) + " at (" + std::to_string(pair[0]) + ", " +
                               std::to_string(pair[1]) + ", " + std::to_string(pair[2]) + ")";
      const double scale = std::max(point.subsurface[c], point.btdf[c]);
      EXPECT_TRUE(close(tables.channels[c].brdf_subsurface(theta_i, theta_o, phi), point.subsurface[c], scale))
          << what << " BRDF";
      EXPECT_TRUE(close(tables.channels[c].btdf(theta_i, theta_o, phi), point.btdf[c], scale)) << what << " BTDF";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(MaterialSolve, EveryLayeredPreset, ::testing::ValuesIn(layered_presets()), test_name);
INSTANTIATE_TEST_SUITE_P(MaterialSolve, EveryPreset, ::testing::ValuesIn(preset_names()), test_name);

}  // namespace
}  // namespace skinlayer
