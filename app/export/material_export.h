// One material written in one of the tabulated exchange formats, whole, as bytes: the one path that
// `skinlayer export`, the previewer's export buttons and the Python module's Solution.export take.
//   SCATFUN (.bsdf): the Fourier BSDF that pbrt-v3 reads (app/export/fourier_bsdf_export.h), `nodes` polar nodes;
//   MERL (.binary): the 90 x 90 x 180 half/difference table (app/export/merl_brdf.h);
//   RGL (.rgl.bsdf): the tensor file of pbrt-v4 and Mitsuba 3 (app/export/rgl_export.h), spectral or rgb.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "app/export/fourier_bsdf_export.h"
#include "app/export/rgl_export.h"
#include "app/material/material_document.h"
#include "app/solution/material_solve.h"

namespace skinlayer {

enum class TabulatedFormat { Scatfun, Merl, RglSpectral, RglRgb };

struct ExportSettings {
  TabulatedFormat format = TabulatedFormat::RglSpectral;
  int nodes = kDefaultScatfunNodes;  // SCATFUN only
  RglOptions rgl;                    // RGL only
  std::string description;           // RGL only: the file's description (rgl_description)
};

// "SCATFUN", "MERL", "RGL tensor, spectral", "RGL tensor, rgb".
std::string_view tabulated_format_label(TabulatedFormat format);

// What an RGL file of skinlayer's says it holds: "skinlayer " and the material file's JSON (material_json.h), so
// that its material can be read back from its description.
std::string rgl_description(const MaterialDocument& document);

// Progress as work finishes (possibly on several threads at once): done of total `unit` ("polar rows").
using ExportProgress = std::function<void(int done, int total, std::string_view unit)>;

// The file's bytes for an already solved material (solve_color). A skin's spectral RGL file solves the skin at each
// of its own wavelengths instead of using `tables`' colour mix. options carry the parallel-for (and SCATFUN's
// upside-down solve).
std::string export_bytes(const ColorTables& tables, const ExportSettings& settings, const SolveOptions& options,
                         const ExportProgress& progress = {});

// The same from the material: solves it first (but for a skin's spectral RGL file, which needs no colour mix).
std::string export_bytes(const ColorMaterial& material, const ExportSettings& settings, const SolveOptions& options,
                         const ExportProgress& progress = {});

}  // namespace skinlayer
