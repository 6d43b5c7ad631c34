// A material document's spatial profile (core/spatial/layer_profile.h) per colour channel, in the document's
// length unit: what `skinlayer profile` writes and the Python module's Solution.profile returns, through the same
// code. So far: layers under an open or rough top, finite or ending in a half-space (a skin among them, mixed from
// its wavelengths), lit by a pencil beam at normal incidence or diffusely; under a rough top (or in diffuse light) a
// rough bottom or a Lambertian base, and rough interfaces between layers over a half-space.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "app/material/material_document.h"
#include "core/spatial/lateral_top_interface.h"
#include "core/spatial/layer_profile.h"

namespace skinlayer {

struct DocumentProfile {
  // Lengths in mm when the layers have their extinction mu_t (1/mm), else in the layer's mean free paths ("mfp").
  std::string unit;
  // [channel][position]: the scattered light leaving the top and the bottom per unit area and unit incident power,
  // in 1/unit^2. One channel for a grey document, three (red, green, blue) for an RGB one.
  std::vector<std::vector<double>> reflectance, transmittance;
};

// The means over the annuli [edges[i], edges[i + 1]) (increasing, from >= 0, in the unit), or the values at radii
// (> 0, in the unit). Throws ParameterError, naming what it cannot take (a rough bottom interface or a Lambertian
// base under an open top, interfaces between layers under an open top or over a finite stack, a stack without every
// layer's mu_t), and for bad positions.
// Where the light enters as radiance spread over directions and leaves a finite stack's bottom, the transmittance is
// computed on 24 nodes at least. With options.reflectance_only the transmittance is left empty.
// The command's resolution: 12 nodes, 16 modes, 40 frequencies.
LayerProfileOptions document_profile_options();

struct ProfileRequest {
  Incidence incidence = Incidence::Normal;
  LayerProfileOptions options = document_profile_options();  // the resolution and the parallel-for
  bool preview = false;  // a skin on its 7 preview wavelengths (color_channels' preview grid) instead of 31
  // Called after each of the document's solves (a skin's wavelengths), with how many are done of how many; empty:
  // none. The command prints it: a skin's profile takes about 18 s.
  std::function<void(int done, int total)> progress = {};
};

DocumentProfile document_profile_in_annuli(const MaterialDocument& document, std::span<const double> edges,
                                           const ProfileRequest& request = {});
DocumentProfile document_profile_at_radii(const MaterialDocument& document, std::span<const double> radii,
                                          const ProfileRequest& request = {});

}  // namespace skinlayer
