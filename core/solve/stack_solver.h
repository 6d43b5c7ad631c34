// The per-mode solve of a stack of layers, one layer being a stack of one (the only solver of both): the top
// interface and the bottom (core/interfaces/layer_interfaces.h), a rough interface between layers where the stack has
// one (core/interfaces/internal_interface.h), each slab's homogeneous solutions and, where the open top's beam
// reaches it unscattered, its particular solution, all coupled by one block system (core/solve/stack_boundary.h:
// DISORT's multilayer composition; for one slab, its boundary system). Then out through the top and the bottom:
// through the top interface from the node field, or, without one, by integrating the source function through each
// slab in turn (core/solve/boundary_solve.h's intensity interpolation), face by face.
//
// The unscattered light: the caller evaluates it exactly where it crosses at most two rough interfaces
// (UnscatteredLight of the material: without interfaces between the layers, that of one slab of the total depth)
// and passes its path here, and the same path's node image is left out of the exits, as for one layer: the first
// interface's transmitted source (t12, or an internal interface's beam column under an open top) attenuated over
// the nodes to the second and out through it. Crossing three or more, it stays on the ordinates and the tables.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/interfaces/internal_interface.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/medium/layer_phase.h"
#include "core/solve/stack_boundary.h"
#include "core/solver.h"
#include "core/unscattered/unscattered_light.h"

namespace skinlayer {

class StackSolver {
 public:
  // The top and bottom kernels come from the caller (its cache), for the material's geometry and outside directions
  // (mu_in: light arrives along; mu_out: the tables leave along, none for fluxes only); the internal interfaces' and
  // the layers' phase kernels are built here, or taken from the cache. exact_path: the unscattered path
  // (UnscatteredPath) left out of the exit sums, because the caller evaluates it exactly; None keeps every path on
  // the ordinates. exact_surface_multiple: the top's multiply scattered reflection of the incident light is left out
  // too (UnscatteredLight::brdf holds it); else the tables carry it. `cancelled` is asked while the internal
  // interfaces' and the phase kernels are built (core/cancellation.h).
  StackSolver(const Material& material, const Resolution& resolution, std::shared_ptr<const InterfaceKernels> kernels,
              UnscatteredPath exact_path, bool exact_surface_multiple, SolveCache* cache,
              const ParallelFor& parallel_for, const CancelCheck& cancelled = {});

  struct ModeResult {
    Eigen::MatrixXd reflection;    // K_out x K_in, graphics azimuth convention, 1/sr
    Eigen::MatrixXd transmission;  // K_out x K_in
    StackField field;
  };
  // Mode m for one single-scattering albedo per layer, top to bottom.
  ModeResult solve_mode(int m, std::span<const double> albedos) const;

  // Energy fractions per incident direction (kernels built with these as mu_in) from mode 0 (solve_mode(0, ...)):
  // the DirectionalAlbedo columns and, for two layers or more, in layer_absorptance, what each slab absorbs.
  std::vector<DirectionalAlbedo> directional_albedo(const ModeResult& mode0) const;

  const InterfaceKernels& kernels() const { return *kernels_; }
  int layer_count() const { return static_cast<int>(layers_.size()); }

 private:
  // The beam's amplitude (irradiance on the horizontal) at each slab's top, per incident direction; empty where it
  // does not reach the slab unscattered (a closed top, or a rough interface above).
  const Eigen::VectorXd& beam_amplitude(std::size_t slab) const { return beam_amplitude_[slab]; }
  bool internal_face(std::size_t face) const { return faces_[face] != nullptr; }
  ExitScattering exit_rows(int m, std::size_t slab, double albedo, bool upward) const;
  // The exact two-interface path's node image arriving at its second interface (down, N x K), mode m.
  Eigen::MatrixXd exact_image_at_second(int m) const;

  std::shared_ptr<const InterfaceKernels> kernels_;
  std::vector<StackedLayer> layers_;
  Bottom bottom_;
  std::vector<std::shared_ptr<const PhaseKernels>> phase_;
  std::vector<std::shared_ptr<const InternalInterfaceKernels>> faces_;  // null where the face is index-matched
  std::vector<Eigen::VectorXd> beam_amplitude_;                         // per slab (see beam_amplitude)
  std::vector<Eigen::VectorXd> beam_attenuation_;                       // e^{-tau_i/mu0} per slab
  Eigen::VectorXd beam_at_bottom_;  // the beam's amplitude at the last slab's bottom (empty: none)
  // Where the exact path's interfaces are: kTop, a face index, or kBottom (kNone: no such interface).
  static constexpr int kNone = -3, kTop = -1, kBottom = -2;
  int exact_first_ = kNone, exact_second_ = kNone;
  Eigen::VectorXd exact_between_;  // e^{-tau/mu_j} per node over the depth between them
  UnscatteredPath exact_path_;
  bool exact_surface_multiple_ = false;
  bool want_exit_;
  bool exterior_;  // exits are integrated through the slabs (an open top or an open base)
};

}  // namespace skinlayer
