// A material as the previewer shows it: the layer parameters with an RGB single-scattering albedo (skin is not
// grey), solved one channel per distinct albedo value; or a biophysical skin, solved per wavelength and mixed into
// linear sRGB (app/material/color_channels.h).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "app/material/material_document.h"
#include "core/material.h"
#include "core/models/subsurface_model.h"
#include "core/series/layer_tables.h"
#include "core/solver.h"

namespace skinlayer {

struct ColorMaterial {
  Material layer;  // layer.albedo and layer.below[i].albedo are ignored; albedo_rgb and below_rgb are used instead
  std::array<double, 3> albedo_rgb = {1.0, 1.0, 1.0};
  std::vector<std::array<double, 3>> below_rgb;   // a stack's layers 2..n, one per layer.below
  SubsurfaceModel model = SubsurfaceModel::Stam;  // the comparison models share the surface term (one layer only)
  // Set: a spectral skin (core/skin/skin_optics.h) under layer's top interface, and the albedos above are unused.
  std::optional<SkinParameters> skin;
};

// The material as a file holds it (app/material), and back; a ColorMaterial has no name or description.
MaterialDocument material_document(const ColorMaterial& material);
ColorMaterial color_material(const MaterialDocument& document);

struct ColorTables {
  ColorMaterial material;
  std::array<LayerTables, 3> channels;        // red, green, blue; each on its own grid (their sizes may differ)
  std::array<DirectionalAlbedo, 3> albedo{};  // at albedo_theta_i, per channel
  double albedo_theta_i = 0.0;
  double solve_seconds = 0.0;
};

// Validates the material (every channel) and solves each distinct channel (its layers' albedos) once, on the grid
// and to the modes that channel needs alone (so each channel's tables are its grey solve's); a skin at each
// wavelength of color_channels' grid (the coarser one under options.preview), all on one table grid, each channel
// the weighted sum of the wavelengths' tables and albedos (core/series/weighted_tables.h); a skin under a comparison
// model (Lambert, Hanrahan-Krueger), the one RGB layer that stands for it (app/solution/skin_comparison.h). Also the
// directional albedo at theta_i (radians): the layer's from the solver, or for a comparison model its tables integrated
// over the hemisphere (with the same surface reflectance). Throws ParameterError for invalid parameters. `options` pass
// the caller's cache and parallel-for through to core (SolveOptions).
ColorTables solve_color(const ColorMaterial& material, double theta_i = 0.0, const SolveOptions& options = {});

// The surface term plus the subsurface BRDF of one channel, and the BTDF, in 1/sr (graphics convention, radians).
double brdf_total(const ColorTables& tables, int channel, double theta_i, double theta_o, double phi);
double btdf_total(const ColorTables& tables, int channel, double theta_i, double theta_o, double phi);

}  // namespace skinlayer
