// The spatially resolved response of a layer or a stack of slabs to light entering at a point: where it leaves the
// top and the bottom, averaged over annuli about the entry point or at radii (docs/model.md §21.7, §21.10–21.17).
// Lengths are in mean free paths of the first slab. The light is a pencil beam at normal incidence or diffuse. Above
// the slabs: no interface, a rough one, or a smooth one; below them an index-matched half-space or, under a finite
// stack, nothing, a smooth face (where the beam enters collimated: an open or smooth top), or a rough face or a
// Lambertian base (where the light enters as node radiance: a rough top, or diffuse light).
//
// Single scattering is singular at r -> 0 and is taken in closed form (single_scattering_profile.h for one open slab
// lit by the beam, rough_top_single_scattering.h wherever the light enters through the top's operators), and so is
// the light leaving a finite stack's bottom unscattered or scattered once (transmitted_low_orders.h). The rest, the
// light scattered more than once, is smooth enough for k-space: R_ms(k) = R(k) - R_1(k), where R(k) is the
// discrete-ordinate response at one frequency (lateral_frequency_response.h) and R_1 its first order in the albedo,
// the discrete ordinates' own single scattering (and T_ms = T - T_1 - T_0 likewise). Through an annulus, since
// int_0^a J0(k r) 2 pi r dr = 2 pi a J1(k a) / k, its power is
//   P_ms = int_0^inf R_ms(k) [r1 J1(k r1) - r0 J1(k r0)] dk,
// integrated over a spline of R_ms on a grid uniform in asinh(k / k_s).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/interfaces/microfacet.h"
#include "core/material.h"
#include "core/parallel_for.h"
#include "core/spatial/lateral_bottom_face.h"
#include "core/spatial/lateral_frequency_response.h"
#include "core/spatial/lateral_top_interface.h"

namespace skinlayer {

// The first slab, its top, and the slabs below it (lengths in the first slab's mean free paths, each slab's relative
// extinction saying how its own compare), with the interfaces between them.
struct ProfileLayer {
  double tau = 0.0;                                   // optical depth; +infinity: semi-infinite
  double albedo = 0.0;                                // Omega in [0, 1]
  double g = 0.0;                                     // Henyey-Greenstein asymmetry
  std::optional<RoughDielectric> top = std::nullopt;  // none: no interface (eta = 1)
  std::vector<LateralSlab> below = {};                // the slabs under the first, top to bottom
  Incidence incidence = Incidence::Normal;
  // Smooth (Fresnel) faces instead (§21.14): the top's relative index n_layer / n_above, and under a finite stack the
  // bottom's n_below / n_layer. Unset: none (or the rough `top`).
  std::optional<double> smooth_top = std::nullopt, smooth_bottom = std::nullopt;
  // Under a finite stack, a rough bottom face (eta = n_below / n_layer, in the frame +z up into the layer) or a
  // Lambertian base of this albedo (§21.17). They take light that enters as node radiance (a rough top, or diffuse
  // light).
  std::optional<RoughDielectric> rough_bottom = std::nullopt;
  std::optional<double> lambert_bottom = std::nullopt;
  // Rough interfaces between slabs (§21.16): empty, or one per slab of `below`, the interface above it (eta = n_slab /
  // n_above, != 1), unset where the two are index-matched. They take light that enters as node radiance (a rough top,
  // or diffuse light) and a stack that ends in a half-space, or its reflectance alone.
  std::vector<std::optional<RoughDielectric>> faces = {};

  std::vector<LateralSlab> slabs() const;  // all of them, top to bottom
};

// A material as the profile takes it: its first layer, its top (rough where eta != 1, else none), the layers below in
// the first one's mean free paths, the rough interfaces between them, and under a finite stack its rough bottom or
// Lambertian base. A stack's layers must all have their
// extinction (mu_t), which relates their lengths; throws std::invalid_argument otherwise.
ProfileLayer profile_layer(const Material& material, Incidence incidence = Incidence::Normal);

// The operators that a layer's faces give the ordinates on `ordinates` nodes and `modes` modes, projected on `azimuths`
// samples: what layer_profile builds once at its resolution, and again on finer nodes for the images of the
// unscattered light (§21.17). The entry: none for the open slab's collimated beam (§21.4). The bottom face: none over
// a half-space or where nothing is below.
std::optional<LateralTopInterface> entry_interface(const ProfileLayer& layer, int ordinates, int modes, int azimuths);
std::optional<LateralBottomFace> bottom_face(const ProfileLayer& layer, int ordinates, int modes, int azimuths);

struct LayerProfileOptions {
  LateralFrequencyResolution resolution{16, 24};  // the azimuthal modes at the highest frequencies
  int frequencies = 48;           // samples of R_ms(k)
  double max_frequency = 100.0;   // 1 / mean free path; R_ms is taken as 0 beyond it
  double frequency_scale = 0.01;  // k_s: the grid is uniform in asinh(k / k_s)
  // true: fewer modes where k is low, min(M, 4 + ceil(8 sqrt(k'))), k' the frequency in the mean free paths of the
  // slab that sees it highest (§21.7); false: M at every frequency.
  bool adaptive_modes = true;
  // The caller's parallel-for (core/parallel_for.h): the frequencies are solved side by side through it.
  ParallelFor parallel_for = {};
  // The azimuth samples the interfaces' operators are projected on (lateral_top_interface, lateral_internal_face). The
  // BSDF solve picks its own per material (choose_resolution's interface_azimuths, 49 and up); with its number the
  // profile's R(0) is the solve's to round-off, and 97 is converged within 10^-8 for sigma >= 0.3.
  int interface_azimuths = 97;
  // true: the transmittance is not computed (left empty). Light that enters spread over directions (a rough top,
  // diffuse light) needs finer ordinates for its transmittance than for its reflectance: 24 nodes keep it within 2%
  // of the walk where 12 leave 4.7% (docs/model.md §21.15).
  bool reflectance_only = false;
};

struct LayerProfile {
  // Per annulus [edges[i], edges[i + 1]) (layer_profile: the mean over it) or per radius (layer_profile_at:
  // the value there): the light leaving per unit area and unit incident power (1/mfp^2), all scattering orders; the
  // transmittance leaves out the direct beam (a delta at r = 0). Zero for a semi-infinite layer's bottom.
  std::vector<double> reflectance, transmittance;
  // The same light's totals at k = 0: the directional albedo's subsurface part at normal incidence, less the rough
  // top's own multiply scattered reflection, which leaves at the entry point (LateralTopInterface).
  double total_reflectance = 0.0, total_transmittance = 0.0;
};

// edges: finite, increasing radii from >= 0, in mean free paths. Throws ParameterError (one line for the user) for bad
// edges or radii and for what it cannot take yet (a smooth bottom under a rough top or diffuse light), and
// std::invalid_argument for bad options or layer parameters.
LayerProfile layer_profile(const ProfileLayer& layer, std::span<const double> edges,
                           const LayerProfileOptions& options = {});

// The profile at radii r > 0 (mean free paths): single scattering's density plus
//   R_ms(r) = (1 / 2 pi) int_0^kmax R_ms(k) J0(k r) k dk.
// At r = 0 the profile is infinite (single scattering grows like 1/r), so radii must be > 0.
LayerProfile layer_profile_at(const ProfileLayer& layer, std::span<const double> radii,
                              const LayerProfileOptions& options = {});

}  // namespace skinlayer
