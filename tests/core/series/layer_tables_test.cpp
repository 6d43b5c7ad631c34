#include "core/series/layer_tables.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

// A table holding f_m(theta_i, theta_o) = cos(theta_i)^2 cos(theta_o)^2 (1 + m) on every mode.
LayerTables smooth_tables(int k, int modes) {
  std::vector<double> values;
  for (int m = 0; m < modes; ++m) {
    for (int i = 0; i < k; ++i) {
      for (int o = 0; o < k; ++o) {
        const double ti = LayerTables::grid_angle(i, k), to = LayerTables::grid_angle(o, k);
        values.push_back(std::pow(std::cos(ti) * std::cos(to), 2) * (1.0 + m));
      }
    }
  }
  return LayerTables(k, modes, values, values);
}

TEST(LayerTables, InterpolatesGridValuesExactlyAndSmoothFunctionsClosely) {
  const LayerTables tables = smooth_tables(32, 1);
  const double a = LayerTables::grid_angle(3, 32), b = LayerTables::grid_angle(7, 32);
  EXPECT_NEAR(tables.reflection_mode(0, a, b), std::pow(std::cos(a) * std::cos(b), 2), 1e-15);
  EXPECT_NEAR(LayerTables::grid_coordinate(b, 32), 7.0, 1e-12);
  EXPECT_EQ(LayerTables::grid_angle(31, 32), 0.5 * kPi);
  for (double ti = 0.0; ti <= 1.5707; ti += 0.0937) {
    for (double to = 0.0; to <= 1.5707; to += 0.0611) {
      EXPECT_NEAR(tables.reflection_mode(0, ti, to), std::pow(std::cos(ti) * std::cos(to), 2), 5e-5);
    }
  }
}

TEST(LayerTables, SumsModesWithCosines) {
  const LayerTables tables = smooth_tables(16, 3);
  const double expected = 1.0 * 1.0 + 2.0 * std::cos(0.7) + 3.0 * std::cos(1.4);  // at theta = 0 both
  EXPECT_NEAR(tables.brdf_subsurface(0.0, 0.0, 0.7), expected, 1e-12);
  EXPECT_THROW(LayerTables(16, 2, std::vector<double>(10), std::vector<double>(10)), std::invalid_argument);
}

// No medium (T = 1) over an index-matched bottom: the BTDF is the top's refraction lobe, at sigma 0.05 and eta 2.5
// narrower than a grid step. The signed spline sum dips below zero beside it (by percents of the peak); the BSDF
// accessors must not: they clamp, and only where the sum is negative.
TEST(LayerTables, BsdfIsNonNegativeBesideALobeNarrowerThanAGridStep) {
  Material material;
  material.sigma = 0.05;
  material.eta = 2.5;
  material.tau = 0.0;
  material.bottom.kind = BottomKind::Matched;
  SolveOptions all_ordinates;  // the lobe on the tables, as the published method puts it (no exact unscattered part)
  all_ordinates.exact_unscattered = false;
  const LayerTables tables = solve(material, all_ordinates);
  const double theta_i = degrees_to_radians(30.0);
  struct Point {
    double theta_o, sum, btdf;
  };
  std::vector<Point> points;
  double lowest_sum = 0.0, peak = 0.0;
  for (int step = 0; step <= 900; ++step) {
    const double theta_o = degrees_to_radians(0.1 * step);
    for (const double phi : {0.0, kPi}) {
      double sum = 0.0;
      for (int m = 0; m < tables.modes(); ++m) sum += tables.transmission_mode(m, theta_i, theta_o) * std::cos(m * phi);
      points.push_back({0.1 * step, sum, tables.btdf(theta_i, theta_o, phi)});
      lowest_sum = std::min(lowest_sum, sum);
      peak = std::max(peak, sum);
    }
  }
  for (const Point& point : points) {
    EXPECT_GE(point.btdf, 0.0) << "theta_o " << point.theta_o;
    // The clamp leaves a non-negative sum as it is. The two sums add the same terms in another order (btdf's may
    // fuse multiply-adds: core/series/window_sum.h), so they agree to rounding of the terms, which are up to the
    // peak: far from the lobe that is more than 1e-12 of the value.
    if (point.sum >= 0.0) {
      EXPECT_NEAR(point.btdf, point.sum, 1e-12 * (point.sum + peak)) << "theta_o " << point.theta_o;
    }
  }
  EXPECT_LT(lowest_sum, -1e-3 * peak) << "the case no longer undershoots: it no longer tests the clamp";
}

// The spline between grid angles, checked against a solve on a grid twice as fine, whose nodes at odd degrees sit
// halfway between the coarse grid's nodes.
TEST(LayerTables, SplineBetweenGridAnglesMatchesAFinerSolve) {
  const Material material;
  SolveOptions coarse_options, fine_options;
  coarse_options.table_size = 46;  // 2 degree spacing
  fine_options.table_size = 91;    // 1 degree spacing
  const LayerTables coarse = solve(material, coarse_options);
  const LayerTables fine = solve(material, fine_options);
  double worst = 0.0;
  for (int ti = 1; ti < 89; ti += 6) {
    for (int to = 1; to < 89; to += 4) {
      for (double phi : {0.0, 90.0, 180.0}) {
        const double a =
            coarse.brdf_subsurface(degrees_to_radians(ti), degrees_to_radians(to), degrees_to_radians(phi));
        const double b = fine.brdf_subsurface(degrees_to_radians(ti), degrees_to_radians(to), degrees_to_radians(phi));
        worst = std::max(worst, std::abs(a - b) / b);
      }
    }
  }
  EXPECT_LT(worst, 2e-3);
}

}  // namespace
}  // namespace skinlayer

namespace skinlayer {
namespace {

// A matched-bottom layer's tables on a coarse grid of 12 angles.
LayerTables twelve_point_tables() {
  Material m;
  m.bottom = parse_bottom("matched");
  SolveOptions options;
  options.table_size = 12;
  return solve(m, options);
}

TEST(LayerTables, RefinedTablesHoldTheSplineAtTheFinerGridAngles) {
  const LayerTables coarse = twelve_point_tables();
  const LayerTables fine = coarse.refined(3);
  ASSERT_EQ(fine.grid_size(), 34);
  ASSERT_EQ(fine.modes(), coarse.modes());
  for (int m_index : {0, 1, 2}) {
    for (int i = 0; i < fine.grid_size(); i += 5) {
      for (int o = 0; o < fine.grid_size(); o += 3) {
        const double ti = LayerTables::grid_angle(i, fine.grid_size());
        const double to = LayerTables::grid_angle(o, fine.grid_size());
        const double expected_r = coarse.reflection_mode(m_index, ti, to);
        const double expected_t = coarse.transmission_mode(m_index, ti, to);
        const std::size_t index = (static_cast<std::size_t>(m_index) * fine.grid_size() + i) * fine.grid_size() + o;
        EXPECT_NEAR(fine.reflection_coefficients()[index], expected_r, 1e-12 * (1.0 + std::abs(expected_r)));
        EXPECT_NEAR(fine.transmission_coefficients()[index], expected_t, 1e-12 * (1.0 + std::abs(expected_t)));
      }
    }
  }
}

// A grid of any size on the same map, finer or coarser and no multiple of this one's: each value is the spline at
// the new grid's angle, the ends (normal and grazing) are this grid's own samples, and refined(2) is resampled to
// 2 (K - 1) + 1 points bit for bit.
TEST(LayerTables, ResampledTablesHoldTheSplineAtTheNewGridAngles) {
  const LayerTables tables = twelve_point_tables();
  for (const int size : {7, 17, 30}) {
    const LayerTables other = tables.resampled(size);
    ASSERT_EQ(other.grid_size(), size);
    ASSERT_EQ(other.modes(), tables.modes());
    for (int m_index : {0, 1, 3}) {
      for (int i = 0; i < size; ++i) {
        for (int o = 0; o < size; o += 2) {
          const double ti = LayerTables::grid_angle(i, size), to = LayerTables::grid_angle(o, size);
          const double expected_r = tables.reflection_mode(m_index, ti, to);
          const double expected_t = tables.transmission_mode(m_index, ti, to);
          const std::size_t index = (static_cast<std::size_t>(m_index) * size + i) * size + o;
          EXPECT_NEAR(other.reflection_coefficients()[index], expected_r, 1e-12 * (1.0 + std::abs(expected_r)));
          EXPECT_NEAR(other.transmission_coefficients()[index], expected_t, 1e-12 * (1.0 + std::abs(expected_t)));
        }
      }
    }
    const auto corner = [](const LayerTables& t, int i, int o) {
      return t.reflection_coefficients()[static_cast<std::size_t>(i) * t.grid_size() + o];
    };
    EXPECT_EQ(corner(other, 0, 0), corner(tables, 0, 0));
    EXPECT_EQ(corner(other, size - 1, size - 1), corner(tables, 11, 11));
  }
  const LayerTables twice = tables.refined(2);
  EXPECT_TRUE(std::ranges::equal(twice.reflection_coefficients(), tables.resampled(23).reflection_coefficients()));
}

}  // namespace
}  // namespace skinlayer
