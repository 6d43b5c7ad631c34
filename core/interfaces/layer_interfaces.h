// The interface half of a solve: the layer's geometry (which interfaces exist) and every Fourier-projected interface
// operator between the ordinates and the outside directions (Stam 2001's t12, R21, R23 and the exits), energy-matched
// to the interfaces' slope-space albedos. They depend on the interfaces (sigma and eta of top and bottom, the bottom's
// kind), the resolution and the outside directions, never on the albedo, the depth or the phase function, so a
// SolveCache (core/solve/solve_cache.h) keeps them across re-solves that change only those.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <span>
#include <vector>

#include "core/cancellation.h"
#include "core/interfaces/interface_albedo.h"
#include "core/interfaces/interface_operators.h"
#include "core/interfaces/microfacet.h"
#include "core/interfaces/multiple_scattering.h"
#include "core/material.h"
#include "core/parallel_for.h"
#include "core/series/fourier.h"
#include "core/series/quadrature.h"

namespace skinlayer {

enum class LayerBase { Rough, Open, Lambert };

struct LayerGeometry {
  bool top_open = false;  // eta = 1: no top interface, the incident beam enters unscattered
  LayerBase base = LayerBase::Rough;
  RoughDielectric top;
  RoughDielectric bottom;           // frame +z up into the layer: eta = n_below / n_layer
  bool bottom_mirrors_top = false;  // the bottom is the top mirrored: R23 = R21 and T23 = T21

  bool operator==(const LayerGeometry&) const = default;
};
LayerGeometry classify_layer(const Material& material);

// The material's top interface (eta, sigma) and its bottom in the frame +z up into the layer (eta = n_below / n_layer
// = 1 / bottom_eta()), each with the material's microfacet model; what every part of a solve takes them as.
RoughDielectric top_interface(const Material& material);
RoughDielectric bottom_interface(const Material& material);

// A Lambertian base of albedo A under the ordinates (f = A/pi, Fourier mode 0 only), as a node operator from the
// down nodes to the up nodes: R(o, j) = c_0 (A/pi) mu_j a_j = 2 A mu_j a_j.
Eigen::MatrixXd lambert_reflection(const QuadratureRule& quadrature, double albedo);

// Everything interface-dependent of one solve, in propagation convention (core/conventions.h), before the per-mode
// parity. Kernels with "rows" map node radiance to outside directions; each is empty where the geometry has no use
// for it. Node operators (r_top, r_bottom, t_exit, ...) carry the quadrature weights (apply_quadrature_weights).
struct InterfaceKernels {
  LayerGeometry geometry;
  QuadratureRule quadrature;          // double-Gauss, N per hemisphere
  std::vector<double> mu_in, mu_out;  // the outside cosines of the columns and of the exit rows
  // Per node, the albedos of the top interface for light travelling up to it and of the bottom interface for light
  // travelling down to it (R = 0, T = 1 where there is no interface): the energy targets of R21 and R23.
  std::vector<InterfaceAlbedo> top_inside, bottom_inside;
  // Per incident direction (mu_in), the top's albedo parts for the incident light, the energy targets of t_source
  // (R = 0, T = 1 under an open top), and under an open top the rough bottom's albedos for the beam, those of
  // s_bottom_beam (empty otherwise): StackSolver::directional_albedo reads them too.
  std::vector<InterfaceAlbedoParts> top_outside;
  std::vector<InterfaceAlbedo> bottom_beam_albedo;
  FourierKernel r_top, r_top_rows;
  FourierKernel r_bottom, s_bottom_beam, r_bottom_rows;
  // The kernels whose single scattering the exact unscattered light replaces, with their multiply scattered part
  // apart (InterfaceKernel; none under MicrofacetModel::Single).
  InterfaceKernel t_source, t_exit, t_source_exterior, t_bottom_exit, t_bottom_beam, r_bottom_beam_rows;
  // Under MicrofacetModel::Multiple, the top's multiply scattered reflection from outside to the exit rows, which
  // the tables carry (brdf_surface is the single scattering's specular lobe alone), per mode; empty otherwise.
  FourierKernel r_surface_multiple;
  // The rough interfaces' multiply scattered lobes the kernels were built from (null under MicrofacetModel::Single,
  // without the interface, or for a bottom that mirrors the top), for the exact unscattered light to share.
  std::shared_ptr<const MultipleScatteringLobe> top_multiple, bottom_multiple;

  std::size_t bytes() const;  // the kernels' memory
};

// The cosines with their signs flipped: the same polar angles travelling the other way.
std::vector<double> negated(std::span<const double> cosines);

// Which kernels to build: all that the geometry uses; all but the top's multiply scattered reflection from outside
// to the exit rows (r_surface_multiple), where the exact unscattered light evaluates it instead; or only those of the
// unscattered light's first bottom reflection (t_source, t_exit, r_bottom; core/unscattered/bottom_bounce.h), which
// the solver builds again on finer ordinates.
enum class KernelSet { All, AllButSurfaceMultiple, BottomBounce };

// mu_in: the outside cosines light arrives along (clamped off 0 by the caller); mu_out: those the tables leave along,
// either none (fluxes only) or the same as mu_in. ordinates N, Fourier modes projected and azimuth samples as the
// resolution says. The independent kernels (top reflection, top transmission, bottom ...) run through parallel_for
// when it is given (SolveOptions::parallel_for); the result is the same either way. `cancelled` is asked once per
// incident direction of every kernel (interface_fourier), so a cancelled solve stops inside the build.
InterfaceKernels interface_kernels(const LayerGeometry& geometry, int ordinates, int max_modes, int interface_azimuths,
                                   std::span<const double> mu_in, std::span<const double> mu_out,
                                   const ParallelFor& parallel_for = {}, KernelSet set = KernelSet::All,
                                   const CancelCheck& cancelled = {});

}  // namespace skinlayer
