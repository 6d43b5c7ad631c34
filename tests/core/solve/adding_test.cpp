// Slab operators (core/medium/slab_operators.h) and the adding equations (core/solve/adding.h), the building blocks of
// stacked layers: checked against facts that do not come from the same formulas: a slab split in two halves adds back to
// the whole (doubling), a semi-infinite slab is unchanged by a slab of itself on top, a conservative slab loses no
// flux, and adding a reflecting base gives what the boundary solve gives with that base as its bottom condition.
#include "core/solve/adding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/conventions.h"
#include "core/medium/henyey_greenstein.h"
#include "core/medium/slab_operators.h"
#include "core/series/fourier.h"
#include "core/series/quadrature.h"
#include "core/solve/boundary_solve.h"

namespace skinlayer {
namespace {

struct Medium {
  double albedo;
  double g;
};

// The slab's eigen-decomposition of mode m on N = 16 double-Gauss ordinates.
class SlabOperators : public ::testing::Test {
 protected:
  static constexpr int kOrdinates = 16;
  static constexpr int kModes = 8;
  SlabEigenSolution eigen(const Medium& medium, int m) const {
    const PhaseMatrices phase = henyey_greenstein_matrices(medium.g, quadrature_.nodes, quadrature_.weights,
                                                           CosineProjector(kModes, 4 * kModes + 1));
    return slab_eigen(quadrature_.nodes, quadrature_.weights, phase.same[m], phase.opposite[m],
                      medium.albedo * fourier_azimuth_weight(m));
  }
  QuadratureRule quadrature_ = double_gauss_half_range(kOrdinates);
};

double max_abs_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).cwiseAbs().maxCoeff(); }

TEST_F(SlabOperators, TwoHalvesAddUpToTheWholeSlab) {
  for (const Medium medium : {Medium{0.5, 0.0}, Medium{0.99, 0.8}, Medium{0.9, -0.5}}) {
    for (const int m : {0, 1, 4}) {
      for (const double tau : {0.05, 1.0, 6.0}) {
        const SlabEigenSolution solution = eigen(medium, m);
        const LayerOperators whole = slab_operators(solution, tau);
        const LayerPair half = symmetric_layer(slab_operators(solution, 0.5 * tau));
        const LayerPair added = add_layers(half, half);
        const auto where = ::testing::Message()
                           << "albedo " << medium.albedo << " g " << medium.g << " m " << m << " tau " << tau;
        EXPECT_LT(max_abs_difference(added.from_above.reflection, whole.reflection), 1e-9) << where;
        EXPECT_LT(max_abs_difference(added.from_above.transmission, whole.transmission), 1e-9) << where;
        EXPECT_LT(max_abs_difference(added.from_below.reflection, whole.reflection), 1e-9) << where;
        EXPECT_LT(max_abs_difference(added.from_below.transmission, whole.transmission), 1e-9) << where;
      }
    }
  }
}

// Different slabs, so that light from above and from below differ: the stack seen from below is the flipped stack
// seen from above; adding is associative; and a pair over a base reflects as the top slab over (the bottom slab over
// the base).
TEST_F(SlabOperators, UnlikeSlabsAddConsistentlyInEveryOrder) {
  for (const int m : {0, 3}) {
    const LayerPair a = symmetric_layer(slab_operators(eigen(Medium{0.95, 0.8}, m), 0.4));
    const LayerPair b = symmetric_layer(slab_operators(eigen(Medium{0.6, -0.3}, m), 1.5));
    const LayerPair c = symmetric_layer(slab_operators(eigen(Medium{0.99, 0.2}, m), 0.2));
    const LayerPair ab = add_layers(a, b);
    const LayerPair ba = add_layers(b, a);
    EXPECT_LT(max_abs_difference(ab.from_below.reflection, ba.from_above.reflection), 1e-12) << "m " << m;
    EXPECT_LT(max_abs_difference(ab.from_below.transmission, ba.from_above.transmission), 1e-12) << "m " << m;
    EXPECT_GT(max_abs_difference(ab.from_above.reflection, ba.from_above.reflection), 1e-3) << "the order matters";
    const LayerPair left = add_layers(ab, c);
    const LayerPair right = add_layers(a, add_layers(b, c));
    EXPECT_LT(max_abs_difference(left.from_above.reflection, right.from_above.reflection), 1e-12) << "m " << m;
    EXPECT_LT(max_abs_difference(left.from_above.transmission, right.from_above.transmission), 1e-12) << "m " << m;
    EXPECT_LT(max_abs_difference(left.from_below.reflection, right.from_below.reflection), 1e-12) << "m " << m;
    EXPECT_LT(max_abs_difference(left.from_below.transmission, right.from_below.transmission), 1e-12) << "m " << m;
    const Eigen::MatrixXd base = slab_operators(eigen(Medium{0.9, 0.5}, m), INFINITY).reflection;
    EXPECT_LT(max_abs_difference(reflection_over(ab, base), reflection_over(a, reflection_over(b, base))), 1e-12);
  }
}

TEST_F(SlabOperators, ThinSlabsTransmitTheUnscatteredBeamOnTheDiagonal) {
  const SlabEigenSolution solution = eigen(Medium{0.0, 0.0}, 0);
  const double tau = 0.7;
  const LayerOperators slab = slab_operators(solution, tau);
  for (int j = 0; j < kOrdinates; ++j) {
    EXPECT_NEAR(slab.transmission(j, j), std::exp(-tau / quadrature_.nodes[j]), 1e-12);
    EXPECT_NEAR(slab.reflection.col(j).cwiseAbs().maxCoeff(), 0.0, 1e-12) << "nothing scatters back";
  }
}

TEST_F(SlabOperators, AConservativeSlabLosesNoFlux) {
  // Mode 0, albedo 1 (less 1e-9, as the solver clamps): reflected plus transmitted flux equals the incident flux,
  // sum_i mu_i a_i (R + T)(i, j) = mu_j a_j, for every incident node.
  const SlabEigenSolution solution = eigen(Medium{1.0 - 1e-9, 0.8}, 0);
  const LayerOperators slab = slab_operators(solution, 2.0);
  for (int j = 0; j < kOrdinates; ++j) {
    double out = 0.0;
    for (int i = 0; i < kOrdinates; ++i) {
      out += quadrature_.nodes[i] * quadrature_.weights[i] * (slab.reflection(i, j) + slab.transmission(i, j));
    }
    EXPECT_NEAR(out / (quadrature_.nodes[j] * quadrature_.weights[j]), 1.0, 1e-7) << "node " << j;
  }
}

TEST_F(SlabOperators, ASemiInfiniteSlabIsUnchangedByASlabOfItselfOnTop) {
  for (const int m : {0, 2}) {
    const SlabEigenSolution solution = eigen(Medium{0.95, 0.7}, m);
    const Eigen::MatrixXd infinite = slab_operators(solution, INFINITY).reflection;
    const Eigen::MatrixXd covered = reflection_over(symmetric_layer(slab_operators(solution, 0.8)), infinite);
    EXPECT_LT(max_abs_difference(covered, infinite), 1e-9) << "m " << m;
  }
}

TEST_F(SlabOperators, AddingABaseEqualsTheBoundarySolveWithThatBase) {
  // A base that reflects a fixed fraction of each node's flux diffusely (a Lambertian floor of albedo 0.6 in mode
  // 0): R_base(i, j) = 2 A mu_j a_j. The boundary solve takes it as its bottom condition directly.
  const SlabEigenSolution solution = eigen(Medium{0.8, 0.6}, 0);
  Eigen::MatrixXd base(kOrdinates, kOrdinates);
  for (int i = 0; i < kOrdinates; ++i) {
    for (int j = 0; j < kOrdinates; ++j) base(i, j) = 2.0 * 0.6 * quadrature_.nodes[j] * quadrature_.weights[j];
  }
  BoundaryProblem problem;
  problem.eigen = &solution;
  problem.tau = 1.3;
  problem.reflect_bottom = base;
  problem.source_top = Eigen::MatrixXd::Identity(kOrdinates, kOrdinates);
  const NodeField field = solve_boundary(problem, kOrdinates);
  const Eigen::MatrixXd added = reflection_over(symmetric_layer(slab_operators(solution, 1.3)), base);
  EXPECT_LT(max_abs_difference(added, field.up_top), 1e-10);
}

}  // namespace
}  // namespace skinlayer
