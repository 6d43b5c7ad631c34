// A solved RGB material (app/solution/material_solve.h) in the exchange formats: what `skinlayer export` and the
// previewer's Export buttons both write.
#pragma once

#include <functional>
#include <string>

#include "app/export/fourier_bsdf_export.h"
#include "app/export/merl_brdf.h"
#include "app/solution/material_solve.h"

namespace skinlayer {

// The MERL file's bytes of the tables' reflection (surface + subsurface, each channel; one evaluation for a grey
// material). progress and parallel_for as for encode_merl.
std::string merl_file(const ColorTables& tables, const std::function<void(int, int)>& progress = {},
                      const std::function<void(int, const std::function<void(int)>&)>& parallel_for = {});

// The SCATFUN file's bytes (fourier_bsdf_export.h) of the solved material: it solves the material upside down for
// light from below (through `options`, as solve_color), then tabulates both on `nodes` polar nodes per hemisphere.
// progress(done, total) counts polar rows.
std::string scatfun_file(const ColorTables& tables, int nodes, const SolveOptions& options = {},
                         const std::function<void(int, int)>& progress = {});

}  // namespace skinlayer
