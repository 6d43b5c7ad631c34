// What an RGL tensor file (app/export/rgl_export.h) holds of a material, in its three forms:
//   rgb        the material's linear-sRGB BRDF, surface plus subsurface (Mitsuba 3's RGB variants);
//   spectral   a skin's own spectrum: its BRDF at each wavelength it is solved at (400-700 nm, 10 nm steps);
//              any other material's RGB value at each direction pair raised to a smooth spectrum
//              (core/color/rgb_uplift.h) on kUpliftWavelengths (pbrt-v4, Mitsuba 3's spectral variants).
#pragma once

#include <array>

#include "app/export/rgl_export.h"
#include "app/solution/material_solve.h"

namespace skinlayer {

// The uplifted spectra's wavelengths, nm: 380-740 in 60 nm steps, constant beyond (as both readers extend a
// spectrum). Seven, so that the default material's file stays under 10 MB; the sigmoid is fitted to the spectrum as
// written (read linearly between these), so its colour is the RGB value's.
inline constexpr std::array<double, 7> kUpliftWavelengths = {380.0, 440.0, 500.0, 560.0, 620.0, 680.0, 740.0};

// The rgb form of solved tables. The channels read `tables`, which must outlive them (as in the next function).
RglChannels rgl_rgb_channels(const ColorTables& tables);

// The spectral form of an RGB (or grey) material's solved tables.
RglChannels rgl_uplifted_channels(const ColorTables& tables);

// The spectral form of a skin: solves it at each wavelength of its colour grid (options pass the caller's cache and
// parallel-for). Throws std::invalid_argument unless material.skin is set, ParameterError for invalid parameters.
RglChannels rgl_skin_channels(const ColorMaterial& material, const SolveOptions& options);

}  // namespace skinlayer
