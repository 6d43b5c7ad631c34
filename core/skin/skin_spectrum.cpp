#include "core/skin/skin_spectrum.h"

#include <algorithm>

#include "core/solve/solve_cache.h"

namespace skinlayer {

std::vector<std::vector<DirectionalAlbedo>> skin_directional_albedo(const SkinParameters& skin,
                                                                    const Material& interfaces,
                                                                    std::span<const double> wavelengths_nm,
                                                                    std::span<const double> theta_i,
                                                                    const SolveOptions& options) {
  validate(skin);
  std::vector<std::vector<DirectionalAlbedo>> rows(wavelengths_nm.size());
  if (wavelengths_nm.empty()) return rows;
  SolveCache own_cache;
  SolveOptions first = options;
  if (first.cache == nullptr) first.cache = &own_cache;
  first.parallel_for = {};
  rows[0] = directional_albedo(skin_material(skin, wavelengths_nm[0], interfaces), theta_i, first);
  // The rest side by side in chunks, each with a copy of the warm cache (as solve_batch, core/solve/batch_solve.h).
  const std::size_t rest = wavelengths_nm.size() - 1;
  const std::size_t chunks = options.parallel_for ? std::min<std::size_t>(4, rest) : std::min<std::size_t>(1, rest);
  std::vector<SolveCache> caches(chunks, *first.cache);
  run_parallel(options.parallel_for, static_cast<int>(chunks), [&](int chunk) {
    SolveOptions one = first;
    one.cache = &caches[static_cast<std::size_t>(chunk)];
    for (std::size_t k = 1 + static_cast<std::size_t>(chunk); k < wavelengths_nm.size(); k += chunks) {
      rows[k] = directional_albedo(skin_material(skin, wavelengths_nm[k], interfaces), theta_i, one);
    }
  });
  return rows;
}

}  // namespace skinlayer
