// The response of a layer to light at one lateral spatial frequency: the first step from the BSDF, which integrates
// over the whole surface, to the spatially resolved response (docs/model.md §21).
//
// A pencil beam of unit power enters at the origin of the top face. Transformed in the lateral coordinates,
// I(k) = int I(x) e^{-i k.x} d^2x, the transport equation for each spatial frequency k (along x) reads, in optical
// depth tau (downward) and mean free paths:
//   mu dI/dtau + (1 + i k sin(theta) cos(phi)) I = Omega int p I' d omega' + Omega p(mu) e^{-tau},
// where mu = cos(theta) is signed (mu > 0 travels down) and the last term is the first scattering of the beam.
// R(k) and T(k), the scattered light leaving the top and the bottom per unit incident power, are the Hankel
// transforms of the profiles: R(k) = int_0^inf R(r) J0(k r) 2 pi r dr, so R(0) is the subsurface reflectance.
//
// A stack of homogeneous slabs (lateral_slab_modes.h), index-matched or with rough interfaces between them
// (lateral_internal_face.h), and below it an index-matched half-space, nothing or a face (lateral_bottom_face.h). Above
// it: no interface (eta = 1, the open layer), a rough one or a smooth one (lateral_top_interface.h), through the BSDF's
// own operators. Light at normal incidence or diffuse.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/spatial/lateral_internal_face.h"

namespace skinlayer {

struct LateralTopInterface;
struct LateralBottomFace;

struct LateralFrequencyResolution {
  int ordinates = 16;      // double-Gauss nodes per hemisphere
  int azimuth_modes = 24;  // cosine modes m = 0 .. azimuth_modes - 1 that the k.s term couples
};

struct LateralFrequencyResponse {
  double reflectance = 0.0;    // R(k): scattered light out of the top, per unit incident power
  double transmittance = 0.0;  // T(k): scattered light out of the bottom (the direct beam, a delta at r = 0, is not
                               // in it); 0 for a semi-infinite layer
};

// One slab of a stack. Lengths are in mean free paths of the first slab, so a slab whose extinction mu_t differs
// from the first's sees the frequency k / relative_extinction in its own mean free paths.
struct LateralSlab {
  double tau = 0.0;                  // optical depth; +infinity (semi-infinite) for the last slab only
  double albedo = 0.0;               // Omega in [0, 1]
  double g = 0.0;                    // Henyey-Greenstein asymmetry
  double relative_extinction = 1.0;  // mu_t / the first slab's mu_t
};

// A stack's depths, in the first slab's mean free paths: the optical depth T_l and the geometric depth G_l above each
// slab, and the totals tau and H (infinite when the last slab is).
struct StackDepths {
  std::vector<double> optical, geometric;
  double tau = 0.0, height = 0.0;
};
StackDepths stack_depths(std::span<const LateralSlab> slabs);

// The stack's response at k (1 / the first slab's mean free path) under an open top (top null: a collimated beam
// scattered in each slab with its own albedo), a rough one, diffuse light, or a smooth top (lateral_top_interface.h,
// built for `resolution`), over an index-matched half-space or a bottom face (bottom, for a finite stack).
// faces: empty, or per slab the rough interface above it (lateral_internal_face.h; none above the first), where the
// light enters as node radiance. Throws std::invalid_argument for values outside the ranges above.
LateralFrequencyResponse lateral_stack_response(std::span<const LateralSlab> slabs, const LateralTopInterface* top,
                                                double k, const LateralFrequencyResolution& resolution = {},
                                                const LateralBottomFace* bottom = nullptr,
                                                std::span<const std::optional<LateralInternalFace>> faces = {});

// The first order in the albedos of a collimated beam (under an open top, or a smooth one): the beam scattered once,
// then only streaming and leaving through the top's and the bottom's exits, neither face sending any of it back.
LateralFrequencyResponse collimated_single_scattering_response(std::span<const LateralSlab> slabs,
                                                               const LateralTopInterface* top, double k,
                                                               const LateralFrequencyResolution& resolution = {},
                                                               const LateralBottomFace* bottom = nullptr);

// One slab: tau the optical depth (+infinity: semi-infinite); albedo Omega in [0, 1]; g the Henyey-Greenstein
// asymmetry; k >= 0 in 1 / mean free path. Throws std::invalid_argument for values outside those ranges.
LateralFrequencyResponse open_layer_lateral_response(double tau, double albedo, double g, double k,
                                                     const LateralFrequencyResolution& resolution = {});

// The same under a rough top, whose operators were built for `resolution` (lateral_top_interface). The beam enters
// as the top's refracted node radiance, so the transmittance holds all the light leaving the bottom, the part that
// crossed unscattered included.
LateralFrequencyResponse rough_top_lateral_response(double tau, double albedo, double g, const LateralTopInterface& top,
                                                    double k, const LateralFrequencyResolution& resolution = {});

// The open layer's first order in the albedo: the beam scattered once, then only streaming (the operator
// without scattering). Its k-coupling joins the modes of one node alone, so it costs N small eigen-solves.
LateralFrequencyResponse open_layer_single_scattering_response(double tau, double albedo, double g, double k,
                                                               const LateralFrequencyResolution& resolution = {});

}  // namespace skinlayer
