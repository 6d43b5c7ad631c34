// The one entry point of the subsurface solver: material parameters to tables, and directional albedos.
//
// Method (Stam 2001, with the choices of docs/model.md): Fourier series in azimuth, double-Gauss
// discrete ordinates in polar angle, one half-size symmetric eigen-decomposition per Fourier mode, one boundary
// linear system per mode solved for every incident direction at once, then out through the top (and bottom)
// interface, tabulated on a polar-angle grid and splined.
#pragma once

#include <functional>
#include <span>
#include <stdexcept>
#include <vector>

#include "core/material.h"
#include "core/parallel_for.h"
#include "core/series/layer_tables.h"

namespace skinlayer {

class SolveCache;

struct SolveOptions {
  int table_size = 0;               // polar grid points on [0, pi/2] for the tables; 0 = default
  double fourier_tolerance = 1e-4;  // stop when two successive modes are below this fraction of mode 0's peak
  int max_modes = 0;                // hard cap on Fourier modes; 0 = automatic
  // true: the light that crosses the slab unscattered through the rough interfaces is evaluated exactly at the
  // requested directions (core/unscattered/unscattered_light.h) and the tables hold the rest; false: every path on the
  // discrete ordinates and the tables, as Stam 2001 publishes the method (for convergence studies and comparisons).
  bool exact_unscattered = true;
  // The caller's cache of interface operators (core/solve/solve_cache.h); null = build them for this solve only.
  SolveCache* cache = nullptr;
  // The caller's parallel-for (core/parallel_for.h). The solver runs independent work through it: RGB channels,
  // blocks of Fourier modes, the interface kernels; core itself starts no threads. Empty = one after another.
  ParallelFor parallel_for;
  // A quick look (the previewer's answer while a slider moves, before the full solve): the automatic resolution
  // capped at kPreviewResolution. Where that cap binds (sigma < 0.2, strong forward scattering, near-matched
  // interfaces) the energy fractions stay within 3% of the full solve's (mostly within 0.7%), since the interface
  // operators are matched to the accurate albedos at any N, but the lobes are smeared to the ordinates (pointwise
  // errors of a few percent, up to ~20% near peaks): docs/accuracy.md's figures hold for the full solve only.
  bool preview = false;
  // Asked between stages (after the interface operators, before each Fourier mode): returning true abandons the
  // solve by throwing SolveCancelled. It may be called from the parallel-for's threads at once. Empty = never.
  std::function<bool()> cancelled;
};

// What SolveOptions::preview caps the automatic resolution at: 15-18 ms for an RGB solve on both cores of the 2-core
// VM at the costliest corners of the parameter ranges (docs/benchmarks.md, BM_ResolveColorCorner), where the full
// resolution takes 0.2-1 s.
struct PreviewResolution {
  int ordinates = 32;
  int max_modes = 32;
  int interface_azimuths = 97;
};
inline constexpr PreviewResolution kPreviewResolution{};

// Thrown by a solve whose SolveOptions::cancelled returned true.
class SolveCancelled : public std::runtime_error {
 public:
  SolveCancelled() : std::runtime_error("solve cancelled") {}
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

// True when SolveOptions::preview would solve this material at a coarser resolution than the full solve does.
bool preview_is_coarser(const Material& material);

// Solves the layer (or the stack of layers). Throws ParameterError for an invalid material.
LayerTables solve(const Material& material, const SolveOptions& options = {});

// Solves several channels of one material (RGB): materials that differ in nothing but their layers' albedos,
// sharing every albedo-independent step. One LayerTables per channel, in order. Throws ParameterError for an
// invalid material and std::invalid_argument for channels that differ in anything else.
std::vector<LayerTables> solve(std::span<const Material> channels, const SolveOptions& options = {});

// Solves the layer once per single-scattering albedo of its first layer in `albedos` (material.albedo is ignored),
// sharing every albedo-independent step (interface and phase-function projections): an RGB albedo costs far less
// than three solves. One LayerTables per albedo, in order.
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
  // A stack's (Material::below non-empty) absorptance of each layer, top to bottom: what its medium absorbs; the
  // rest of absorptance is interface_loss and a Lambertian base's share. Empty for a single layer.
  std::vector<double> layer_absorptance;
  double reflectance() const { return reflectance_surface + reflectance_subsurface; }
};
std::vector<DirectionalAlbedo> directional_albedo(const Material& material, std::span<const double> theta_i,
                                                  const SolveOptions& options = {});

// The same for several albedos at once (material.albedo is ignored): one row list per albedo, in order.
std::vector<std::vector<DirectionalAlbedo>> directional_albedo(const Material& material,
                                                               std::span<const double> theta_i,
                                                               std::span<const double> albedos,
                                                               const SolveOptions& options = {});

// The same for several channels of one material (as solve(channels)): one row list per channel, in order.
std::vector<std::vector<DirectionalAlbedo>> directional_albedo(std::span<const Material> channels,
                                                               std::span<const double> theta_i,
                                                               const SolveOptions& options = {});

}  // namespace skinlayer
