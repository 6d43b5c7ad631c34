// Pointwise accuracy of a solve: the BRDF (subsurface) and BTDF of the automatic resolution against a converged solve
// (N 192 ordinates, a table grid twice as fine as the automatic one, at least 95 nodes), judged at individual direction
// pairs, never over bins, wherever the converged value exceeds 1e-3 of the material's peak (issue 10's criterion; a
// peak under 1e-12 1/sr is round-off of a quantity that is exactly 0, and is not judged). The grid of exit directions
// is finer than the lobes near the mirror, straight-through and normal directions.
//
// What this measures is the scattered part's convergence in ordinates, Fourier modes and table nodes: both solves
// share the exact unscattered part (core/unscattered/unscattered_light.h), which
// tests/core/unscattered/unscattered_light_test.cpp judges against closed forms and a brute-force integral.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/material.h"
#include "core/solver.h"

namespace skinlayer {

struct PointError {
  double relative = 0.0;                           // |f - f_converged| / f_converged
  double value = 0.0;                              // f at the automatic resolution [1/sr]
  double converged = 0.0;                          // [1/sr]
  double theta_i = 0.0, theta_o = 0.0, phi = 0.0;  // radians (graphics convention)
  bool transmission = false;
};

struct PointAccuracy {
  PointError worst;            // the largest relative error among the judged points
  int judged = 0;              // points above 1e-3 of the peak
  int ordinates = 0;           // the automatic N
  int table_size = 0;          // the automatic K (table grid nodes)
  double solve_seconds = 0.0;  // the automatic solve's wall time
};

// The exit polar angles judged for one incident angle (radians): every 0.5 degree, plus 0.05-degree steps within
// 3 degrees of the normal, of the mirror angle and of the flat interfaces' straight-through angle.
std::vector<double> judged_exit_angles(const Material& material, double theta_i);

// Compares at theta_i (radians) for each of `incidence`, at phi 0, 90 and 180 degrees and judged_exit_angles.
// `options` apply to both solves (the converged one gets its table size on top): exact_unscattered = false judges
// the all-ordinates method.
PointAccuracy point_accuracy(const Material& material, std::span<const double> incidence,
                             const SolveOptions& options = {});

}  // namespace skinlayer
