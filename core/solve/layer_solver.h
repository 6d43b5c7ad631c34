// The per-mode solve of one layer (a single homogeneous slab, Material::below empty) over shared interface kernels
// (core/interfaces/layer_interfaces.h), with the albedo-independent medium terms of one material: the phase
// function's projections (core/medium/layer_phase.h) and the beam's attenuation. Each mode's eigen-solution
// (core/medium/slab_eigen.h) and boundary system (core/solve/boundary_solve.h) are solved for every incident direction
// at once, then out through the top and the bottom. core/solve/stack_solver.h is its twin for stacks.
#pragma once

#include <memory>
#include <vector>

#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/medium/layer_phase.h"
#include "core/solve/boundary_solve.h"
#include "core/solve/resolution.h"
#include "core/unscattered/unscattered_light.h"

namespace skinlayer {

class SolveCache;

class LayerSolver {
 public:
  // The outside directions are the kernels' (mu_in: light arrives along; mu_out: the tables leave along, none for
  // fluxes only). exact_path: the unscattered path (UnscatteredLight::path) left out of the exit sums, because the
  // caller evaluates it exactly; None keeps every path on the ordinates.
  LayerSolver(const Material& material, const Resolution& resolution, std::shared_ptr<const InterfaceKernels> kernels,
              UnscatteredPath exact_path, SolveCache* cache);

  struct ModeResult {
    Eigen::MatrixXd reflection;    // K_out x K_in, graphics azimuth convention, 1/sr
    Eigen::MatrixXd transmission;  // K_out x K_in
    NodeField field;
  };
  // Mode m for single-scattering albedo `albedo` (everything projected at construction is albedo-independent).
  ModeResult solve_mode(int m, double albedo) const;

  const InterfaceKernels& kernels() const { return *kernels_; }

 private:
  std::shared_ptr<const InterfaceKernels> kernels_;
  const LayerGeometry& geometry_;
  const QuadratureRule& quadrature_;
  double tau_;
  double lambert_;
  const std::vector<double>& mu_in_;
  const std::vector<double>& mu_out_;
  Eigen::VectorXd beam_attenuation_;  // e^{-tau/mu0} per incident direction
  Eigen::VectorXd beam_flux_;         // F = 1/mu0 (so that E_perp mu0 = 1: values are BSDFs)
  bool want_exit_;
  UnscatteredPath exact_path_;        // the unscattered path left out of the exit sums
  Eigen::VectorXd node_attenuation_;  // e^{-tau/mu_j} per node
  std::shared_ptr<const PhaseKernels> phase_kernels_;
};

}  // namespace skinlayer
