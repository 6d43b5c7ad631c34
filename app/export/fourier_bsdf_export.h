// A solved material (app/solution/material_solve.h) as the tabulated Fourier BSDF of app/export/scatfun_file.h, light
// from above and from below, reflection and transmission.
//
// Entry (row, col) for node cosines mu_r, mu_c (propagation against the downward axis) holds the series of
// f |mu_c| in the file's azimuth, a_k(file) = (-1)^k a_k(graphics) (core/conventions.h puts the forward direction at
// phi = pi, the file at 0), f from core/series/bsdf_fourier_series.h:
//   mu_r > 0, mu_c < 0: light from above at acos(mu_r), reflected to acos(-mu_c)         the material's f_r
//   mu_r > 0, mu_c > 0: light from above, transmitted to acos(mu_c) below                the material's f_t
//   mu_r < 0, mu_c > 0: light from below, reflected back down                            the upside-down f_r
//   mu_r < 0, mu_c < 0: light from below, transmitted out the top                        the upside-down f_t
// (core/solve/upside_down.h). Rows and columns at the doubled 0 are empty. A series ends at its last coefficient (in
// any channel) above kScatfunTruncation times the sum of its |a_k| per channel; coefficients below 1e-7 of the largest
// stored value are dropped too. A negative Y a_0 (a table's undershoot at grazing) is written as 0.
#pragma once

#include <functional>
#include <optional>

#include "app/export/scatfun_file.h"
#include "app/solution/material_solve.h"

namespace skinlayer {

inline constexpr int kDefaultScatfunNodes = 64;  // per hemisphere: 128 mu nodes
inline constexpr int kMinScatfunNodes = 8, kMaxScatfunNodes = 512;
inline constexpr double kScatfunTruncation = 1e-4;

// The material seen from below, its RGB albedos reordered with its layers; nullopt for an opaque material.
std::optional<ColorMaterial> upside_down(const ColorMaterial& material);

// above: the material solved; below: upside_down(above.material) solved (nullptr for an opaque one: those rows are
// empty, as is its transmission). nodes per hemisphere in [kMinScatfunNodes, kMaxScatfunNodes]. progress(done, total)
// counts polar rows (possibly from several threads); parallel_for runs them side by side.
ScatfunTable scatfun_table(const ColorTables& above, const ColorTables* below, int nodes,
                           const std::function<void(int, int)>& progress = {}, const ParallelFor& parallel_for = {});

}  // namespace skinlayer
