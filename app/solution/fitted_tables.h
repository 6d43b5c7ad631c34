// A fitted shader as colour tables (core/series/brdf_projection.h): what the previewer pins as B to show the fit
// beside the exact material, with the A/B split. The tables are the shown material's grid and modes, each channel
// the fitted shader's whole BRDF (its specular lobes too), projected; the tables' material is the shown one with an
// index-matched top (eta 1), so that what draws them adds no surface term of its own.
#pragma once

#include <string>

#include "app/solution/material_solve.h"
#include "app/solution/shader_fit.h"
#include "core/parallel_for.h"

namespace skinlayer {

enum class ShaderTarget { Principled, OpenPbr };

struct FittedTables {
  ColorTables tables;
  std::string summary;  // "Principled fit: lobe RMS 1.5 / 1.2 / 1.1%, albedo worst 11.5 / 5.5 / 4.6%"
};

// Fits the shown tables' material and projects the fit. Throws ParameterError for a material the fit cannot take.
FittedTables fitted_tables(const ColorTables& shown, ShaderTarget target, const ParallelFor& parallel_for);

}  // namespace skinlayer
