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
#include "core/series/layer_tables.h"
#include "core/solve/resolution.h"
#include "core/solve/solve_options.h"

namespace skinlayer {

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

// The surface term: the top interface's specular lobe, its single-scattering rough-dielectric BRDF (Fresnel x
// Beckmann x Smith masking-shadowing of the material's microfacet model), in 1/sr. Under MicrofacetModel::Multiple the
// light the top's microsurface reflects after more than one meeting (a lobe of its own, forward like the specular
// one but wider; core/interfaces/multiple_scattering.h) is carried by the tables, in brdf_subsurface.
double brdf_surface(const Material& material, double theta_i, double theta_o, double phi);

// Directional-hemispherical energy fractions for light incident at theta_i (radians).
struct DirectionalAlbedo {
  double theta_i;
  double reflectance_surface;     // reflected by the top interface's specular lobe (brdf_surface)
  double reflectance_subsurface;  // entered, scattered, left through the top; and under MicrofacetModel::Multiple the
                                  // top's multiply scattered reflection (what brdf_subsurface holds)
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
