// PiecewiseLinear2D against closed forms (a uniform and a linear density), against itself (the warp and its inverse
// undo each other, the sampled density is eval's, eval integrates to 1), against a histogram of its own samples, and
// the parameter blend against the definition (a linear mix of the neighbouring slices' normalized densities).
#include "core/sampling/piecewise_linear_2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace skinlayer {
namespace {

// A lumpy positive density on an nx x ny grid, one slice per seed.
std::vector<double> lumpy(int nx, int ny, int slices, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> value(0.05, 3.0);
  std::vector<double> values(static_cast<std::size_t>(nx * ny * slices));
  for (double& v : values) v = value(random);
  return values;
}

TEST(PiecewiseLinear2D, AUniformTableIsTheIdentityAndALinearOneTheSquareRoot) {
  const PiecewiseLinear2D uniform(std::vector<double>(12, 2.0), 4, 3);
  const PiecewiseLinear2D::Sample s = uniform.sample({0.3, 0.8});
  EXPECT_NEAR(s.u[0], 0.3, 1e-12);
  EXPECT_NEAR(s.u[1], 0.8, 1e-12);
  EXPECT_NEAR(s.pdf, 1.0, 1e-12);
  // p(x, y) = 2x: x = sqrt(xi_x), y = xi_y.
  const PiecewiseLinear2D linear(std::vector<double>{0.0, 1.0, 0.0, 1.0}, 2, 2);
  for (const double xi : {0.01, 0.25, 0.5, 0.9}) {
    const PiecewiseLinear2D::Sample t = linear.sample({xi, 0.4});
    EXPECT_NEAR(t.u[0], std::sqrt(xi), 1e-12);
    EXPECT_NEAR(t.u[1], 0.4, 1e-12);
    EXPECT_NEAR(t.pdf, 2.0 * std::sqrt(xi), 1e-12);
  }
}

TEST(PiecewiseLinear2D, TheWarpAndItsInverseUndoEachOtherAndAgreeWithEval) {
  const std::vector<std::vector<double>> params = {{0.0, 0.4, 1.0}, {-1.0, 2.0}};
  const PiecewiseLinear2D table(lumpy(7, 5, 6, 3), 7, 5, params);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0), p0(-0.2, 1.2), p1(-1.5, 2.5);
  for (int n = 0; n < 2000; ++n) {
    const std::vector<double> param = {p0(random), p1(random)};
    const std::array<double, 2> xi = {unit(random), unit(random)};
    const PiecewiseLinear2D::Sample s = table.sample(xi, param);
    const PiecewiseLinear2D::Sample back = table.invert(s.u, param);
    EXPECT_NEAR(back.u[0], xi[0], 1e-9);
    EXPECT_NEAR(back.u[1], xi[1], 1e-9);
    EXPECT_NEAR(s.pdf, table.eval(s.u, param), 1e-9 * s.pdf);
    EXPECT_NEAR(back.pdf, s.pdf, 1e-9 * s.pdf);
  }
}

TEST(PiecewiseLinear2D, EvalIntegratesToOneAndBlendsTheSlicesLinearly) {
  const int nx = 6, ny = 4;
  const std::vector<double> values = lumpy(nx, ny, 2, 9);
  const PiecewiseLinear2D blended(values, nx, ny, {{0.0, 1.0}});
  const PiecewiseLinear2D first(std::vector<double>(values.begin(), values.begin() + nx * ny), nx, ny);
  const PiecewiseLinear2D second(std::vector<double>(values.begin() + nx * ny, values.end()), nx, ny);
  const int steps = 500;  // midpoint rule: exact for a bilinear cell up to its corners' kinks
  double integral = 0.0;
  for (int i = 0; i < steps; ++i) {
    for (int j = 0; j < steps; ++j) {
      const std::array<double, 2> u = {(i + 0.5) / steps, (j + 0.5) / steps};
      const double param[1] = {0.3};
      integral += blended.eval(u, param) / (steps * steps);
      if (i % 50 == 0 && j % 50 == 0) {
        EXPECT_NEAR(blended.eval(u, param), 0.7 * first.eval(u) + 0.3 * second.eval(u), 1e-12);
      }
    }
  }
  EXPECT_NEAR(integral, 1.0, 1e-6);
  const double below[1] = {-5.0}, above[1] = {5.0};  // clamped to the end slices
  EXPECT_NEAR(blended.eval({0.37, 0.61}, below), first.eval({0.37, 0.61}), 1e-12);
  EXPECT_NEAR(blended.eval({0.37, 0.61}, above), second.eval({0.37, 0.61}), 1e-12);
}

TEST(PiecewiseLinear2D, ItsSamplesFollowItsDensity) {
  const int nx = 5, ny = 6;
  const PiecewiseLinear2D table(lumpy(nx, ny, 1, 21), nx, ny);
  const int bins = 8, samples = 200000;
  std::vector<int> counts(bins * bins, 0);
  std::mt19937 random(2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 0; n < samples; ++n) {
    const PiecewiseLinear2D::Sample s = table.sample({unit(random), unit(random)});
    const int bx = std::min(static_cast<int>(s.u[0] * bins), bins - 1),
              by = std::min(static_cast<int>(s.u[1] * bins), bins - 1);
    ++counts[by * bins + bx];
  }
  for (int by = 0; by < bins; ++by) {
    for (int bx = 0; bx < bins; ++bx) {
      double mass = 0.0;  // the bin's probability, by a fine midpoint rule
      for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 40; ++j) mass += table.eval({(bx + (i + 0.5) / 40) / bins, (by + (j + 0.5) / 40) / bins});
      }
      mass /= 1600.0 * bins * bins;
      const double expected = mass * samples, sigma = std::sqrt(expected);
      EXPECT_NEAR(counts[by * bins + bx], expected, 5.0 * sigma) << "bin " << bx << "," << by;
    }
  }
}

TEST(PiecewiseLinear2D, RefusesTablesItCannotNormalize) {
  EXPECT_THROW(PiecewiseLinear2D(std::vector<double>(4, 0.0), 2, 2), std::invalid_argument);
  EXPECT_THROW(PiecewiseLinear2D(std::vector<double>{1.0, -1.0, 1.0, 1.0}, 2, 2), std::invalid_argument);
  EXPECT_THROW(PiecewiseLinear2D(std::vector<double>(5, 1.0), 2, 2), std::invalid_argument);
  EXPECT_THROW(PiecewiseLinear2D(std::vector<double>(3, 1.0), 3, 1), std::invalid_argument);
  const PiecewiseLinear2D table(std::vector<double>(4, 1.0), 2, 2);
  const double extra[1] = {0.5};
  EXPECT_THROW(table.eval({0.5, 0.5}, extra), std::invalid_argument);
}

}  // namespace
}  // namespace skinlayer
