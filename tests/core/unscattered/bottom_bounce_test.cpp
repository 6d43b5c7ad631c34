// The unscattered light's first reflection off a rough bottom (core/unscattered/bottom_bounce.h): its node image
// converges in N far more slowly than the solver's N rule assumes, which is why the solver puts it on four times the ordinates.
#include "core/unscattered/bottom_bounce.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/conventions.h"
#include "core/material.h"
#include "core/series/layer_tables.h"
#include "core/solve/boundary_solve.h"

namespace skinlayer {
namespace {

// The image's value in the forward half of the plane of incidence (graphics phi = pi): the tables hold
// parity(m) B^m, so the sum over m of parity(m) B^m cos(m pi) is the sum of B^m.
Eigen::MatrixXd forward_plane(const Material& m, int ordinates, int modes) {
  const int k = 48;
  std::vector<double> grid(k);
  for (int i = 0; i < k; ++i) grid[i] = std::max(std::cos(LayerTables::grid_angle(i, k)), 1e-6);
  const InterfaceKernels kernels = interface_kernels(classify_layer(m), ordinates, modes, 2 * modes + 1 + 120, grid,
                                                     grid, {}, KernelSet::BottomBounce);
  const Eigen::VectorXd attenuation = slab_attenuation(kernels.quadrature.nodes, m.tau);
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(k, k);
  for (int mode = 0; mode < modes; ++mode) sum += bottom_bounce_image(kernels, attenuation, mode);
  return sum;
}

// The largest relative difference over the entries above 1e-3 of the reference's peak.
double worst_relative(const Eigen::MatrixXd& value, const Eigen::MatrixXd& reference) {
  const double counted = 1e-3 * reference.maxCoeff();
  double worst = 0.0;
  for (Eigen::Index i = 0; i < reference.size(); ++i) {
    if (reference(i) > counted) worst = std::max(worst, std::abs(value(i) - reference(i)) / reference(i));
  }
  return worst;
}

TEST(BottomBounce, TheFinerOrdinatesBringTheImageWithinHalfAPercent) {
  Material m;  // sigma 0.2 at eta 1.4 over its mirror image: N 32 by the automatic rule
  m.sigma = 0.2;
  m.tau = optical_depth_from_transparency(0.5);
  const int modes = 32;
  const Eigen::MatrixXd reference = forward_plane(m, 256, modes);
  const double at_n = worst_relative(forward_plane(m, 32, modes), reference);
  const int finer = bottom_bounce_ordinates(32, RoughDielectric{m.eta, m.sigma});
  EXPECT_EQ(finer, 124) << "4 x ceil(1.75 / (0.2 (1 - 1/1.4)))";
  const double at_4n = worst_relative(forward_plane(m, finer, modes), reference);
  EXPECT_GT(at_n, 0.01) << "the node image at the automatic N errs by percents (why the correction exists)";
  EXPECT_LT(at_4n, 0.005);
  EXPECT_LT(at_4n, 0.5 * at_n);
  RecordProperty("worst_at_32", std::to_string(at_n));
  RecordProperty("worst_at_128", std::to_string(at_4n));
}

TEST(BottomBounce, OrdinatesAreFourTimesTheRefractedLobesNeedFrom96To256) {
  EXPECT_EQ(bottom_bounce_ordinates(24, RoughDielectric{1.4, 0.5}), 96) << "4 x ceil(12.25) = 52, raised to 96";
  EXPECT_EQ(bottom_bounce_ordinates(128, RoughDielectric{1.4, 0.5}), 128) << "never fewer than the solve's N";
  EXPECT_EQ(bottom_bounce_ordinates(124, RoughDielectric{1.4, 0.05}), 256) << "4 x 123, capped";
  EXPECT_EQ(bottom_bounce_ordinates(40, RoughDielectric{1.05, 1.0}), 148);  // 4 x ceil(36.75)
}

TEST(BottomBounce, MattersWhereItsModeZeroReachesFourTenthsOfTheBrdf) {
  Eigen::MatrixXd table = Eigen::MatrixXd::Constant(3, 3, 1.0);
  table(2, 2) = 1e-5;  // below 1e-3 of the peak: not counted
  Eigen::MatrixXd image = Eigen::MatrixXd::Constant(3, 3, 0.3);
  const std::vector<Eigen::MatrixXd> tables = {table};
  EXPECT_FALSE(bottom_bounce_matters(image, tables)) << "0.3 of the BRDF";
  image(0, 1) = -0.5;
  EXPECT_TRUE(bottom_bounce_matters(image, tables)) << "0.5 in magnitude at one entry";
  image(0, 1) = 0.3;
  image(2, 2) = 1.0;
  EXPECT_FALSE(bottom_bounce_matters(image, tables)) << "only where the BRDF is counted";
  EXPECT_FALSE(bottom_bounce_matters(image, {}));
}

}  // namespace
}  // namespace skinlayer
