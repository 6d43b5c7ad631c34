// The one entry point of the subsurface solver: material parameters to tables, and directional albedos.
//
// Method (Stam 2001, with the choices of ../shared/docs/model-spec.md): Fourier series in azimuth, double-Gauss
// discrete ordinates in polar angle, one half-size symmetric eigen-decomposition per Fourier mode, one boundary
// linear system per mode solved for every incident direction at once, then out through the top (and bottom)
// interface, tabulated on a polar-angle grid and splined.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "core/layer_tables.h"
#include "core/material.h"
#include "core/parallel_for.h"

namespace skinlayer {

class SolveCache;

struct SolveOptions {
  int table_size = 0;               // polar grid points on [0, pi/2] for the tables; 0 = default
  double fourier_tolerance = 1e-4;  // stop when two successive modes are below this fraction of mode 0's peak
  int max_modes = 0;                // hard cap on Fourier modes; 0 = automatic
  // true: the light that crosses the slab unscattered through the rough interfaces is evaluated exactly at the
  // requested directions (core/unscattered_light.h) and the tables hold the rest; false: every path on the discrete
  // ordinates and the tables, as Stam 2001 publishes the method (for convergence studies and comparisons).
  bool exact_unscattered = true;
  // The caller's cache of interface operators (core/solve_cache.h); null = build them for this solve only.
  SolveCache* cache = nullptr;
  // The caller's parallel-for (core/parallel_for.h). The solver runs independent work through it: RGB channels,
  // blocks of Fourier modes, the interface kernels; core itself starts no threads. Empty = one after another.
  ParallelFor parallel_for;
};

// The discretization a solve uses, chosen from the material (and its ordinates override).
struct Resolution {
  int ordinates;           // N, discrete ordinates per hemisphere
  int max_modes;           // cap on Fourier modes
  int table_size;          // K, polar grid size of the tables
  int interface_modes;     // Fourier modes the interface operators are projected onto: max_modes rounded up to a
                           // multiple of 16, so that a change of g or of the mode cap keeps them (SolveCache)
  int interface_azimuths;  // azimuth samples on [0, pi] for projecting interface BSDFs
  int phase_azimuths;      // azimuth samples on [0, pi] for projecting the phase function
};
Resolution choose_resolution(const Material& material, const SolveOptions& options = {});

// Solves the layer. Throws ParameterError for an invalid material.
LayerTables solve(const Material& material, const SolveOptions& options = {});

// Solves the layer once per single-scattering albedo in `albedos` (material.albedo is ignored), sharing every
// albedo-independent step (interface and phase-function projections): an RGB albedo costs far less than three
// solves. One LayerTables per albedo, in order.
std::vector<LayerTables> solve(const Material& material, std::span<const double> albedos,
                               const SolveOptions& options = {});

// The surface term: the top interface's rough-dielectric BRDF (Fresnel x Beckmann x Smith), in 1/sr.
double brdf_surface(const Material& material, double theta_i, double theta_o, double phi);

// Directional-hemispherical energy fractions for light incident at theta_i (radians).
struct DirectionalAlbedo {
  double theta_i;
  double reflectance_surface;     // reflected by the top interface
  double reflectance_subsurface;  // entered, scattered, left through the top
  double transmittance;           // left through the bottom (including any unscattered beam)
  double absorptance;             // 1 - reflectance - transmittance: medium, base, and shadowing losses
  double interface_loss;          // the part of absorptance that Smith shadowing-masking removes at the interfaces
  double reflectance() const { return reflectance_surface + reflectance_subsurface; }
};
std::vector<DirectionalAlbedo> directional_albedo(const Material& material, std::span<const double> theta_i,
                                                  const SolveOptions& options = {});

// The same for several albedos at once (material.albedo is ignored): one row list per albedo, in order.
std::vector<std::vector<DirectionalAlbedo>> directional_albedo(const Material& material,
                                                               std::span<const double> theta_i,
                                                               std::span<const double> albedos,
                                                               const SolveOptions& options = {});

}  // namespace skinlayer
