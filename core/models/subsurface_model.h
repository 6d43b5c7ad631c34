// The subsurface models the previewer and the command line can show side by side (Stam's results slides):
// the layer solved by Stam's method, and the Lambert and Hanrahan-Krueger comparison models. Every model comes out
// as LayerTables, so evaluation, figures and rendering share one path; the surface term is the same for all.
#pragma once

#include <optional>
#include <string_view>

#include "core/material.h"
#include "core/series/layer_tables.h"
#include "core/solver.h"

namespace skinlayer {

enum class SubsurfaceModel {
  Stam,              // the layer model (solver.h)
  Lambert,           // lambert_model.h: A/pi with the layer's albedo at normal incidence; no transmission
  HanrahanKrueger,   // hanrahan_krueger.h: single scattering through smooth Fresnel boundaries
};

// "stam", "lambert", "hk". parse_subsurface_model returns nullopt for anything else.
std::string_view subsurface_model_name(SubsurfaceModel model);
std::optional<SubsurfaceModel> parse_subsurface_model(std::string_view name);

// The model's subsurface BRDF and BTDF as tables. Stam: solve(). Lambert: mode 0 only. Hanrahan-Krueger: its
// closed form sampled on the tables' grid and projected onto Fourier modes in azimuth (tolerance as in solve()).
// The comparison models describe one layer: for a stack they throw ParameterError.
LayerTables solve_model(const Material& material, SubsurfaceModel model, const SolveOptions& options = {});

}  // namespace skinlayer
