// The stages of one default solve, rebuilt from core's public building blocks so that each can be timed alone
// (core/solver.cpp runs the same calls inside one class). Inputs are the paper's default material at its automatic
// resolution, with the tables' 48 directions as the incident and exit directions.
#pragma once

#include <vector>

#include "core/material.h"
#include "core/medium/henyey_greenstein.h"
#include "core/medium/slab_eigen.h"
#include "core/series/fourier.h"
#include "core/series/layer_tables.h"
#include "core/series/quadrature.h"
#include "core/solve/boundary_solve.h"
#include "core/solver.h"

namespace skinlayer::bench {

inline constexpr std::uint64_t kMonteCarloBenchPaths = 100000;

// sigma 0.8, g 0.5, the rest default: a material that accepts N = 8 (the default needs N >= 12).
Material ordinate_sweep_material();

struct StageInputs {
  Material material;
  Resolution resolution;
  QuadratureRule quadrature;
  std::vector<double> grid_mu;  // cosines of the tables' polar grid
  int modes = 0;                // Fourier modes the default solve keeps
};
StageInputs default_stage_inputs();

struct InterfaceStage {
  FourierKernel reflect_top;  // R21 between the nodes, energy-matched and weighted
  FourierKernel source_top;   // t12 from the grid directions into the nodes, energy-matched
  FourierKernel exit_top;     // t21 from the nodes out to the grid directions (by reciprocity), weighted
};

PhaseMatrices phase_stage(const StageInputs& in);                 // HG phase matrices, every projected mode
InterfaceStage interface_stage(const StageInputs& in);            // the interface operators, every projected mode
std::vector<SlabEigenSolution> eigen_stage(const StageInputs& in, const PhaseMatrices& phase);  // per kept mode
// The boundary system of every kept mode for all 48 incident directions, and the exit through the top.
double linear_solve_stage(const StageInputs& in, const InterfaceStage& interfaces,
                          const std::vector<SlabEigenSolution>& eigen);
LayerTables spline_stage(const LayerTables& tables);  // the spline tables resampled 2x for the GPU

}  // namespace skinlayer::bench
