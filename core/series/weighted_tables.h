// A linear combination of solved tables: sum_k w_k f_k for tables f_k of the same polar grid. The BSDF is linear in
// the values it is solved for (a spectrum's wavelengths, a colour's channels), so a colour's table is the weighted
// sum of its solves' tables, coefficient by coefficient:
//   S_m(theta_i, theta_o) = sum_k w_k S_m^k(theta_i, theta_o)   (likewise B_m),
// and since the spline is linear in its samples, the sum's spline is the sum of the splines. Tables with fewer
// Fourier modes than the longest contribute zero to the higher modes. [1/sr, as the tables]
#pragma once

#include <span>

#include "core/series/layer_tables.h"

namespace skinlayer {

// Requires tables.size() == weights.size() >= 1, one grid size for all, and one unscattered light for all, up to its
// weight (UnscatteredLight::scaled; its lobes are evaluated exactly, not tabulated, so only the same light adds up:
// the sum's is that light weighted by sum_k w_k times its weight in each table): throws std::invalid_argument
// otherwise. The
// scattered sums keep the tables' clamp at 0 on evaluation, so a sum with negative weights may be clamped where a
// sum of clamped values would not be.
LayerTables weighted_sum(std::span<const LayerTables> tables, std::span<const double> weights);

}  // namespace skinlayer
