#include "core/solve/batch_solve.h"

#include <algorithm>

#include "core/solve/solve_cache.h"

namespace skinlayer {

void for_each_with_warm_cache(std::size_t count, const SolveOptions& options,
                              const std::function<void(std::size_t k, const SolveOptions& options)>& body) {
  if (count == 0) return;
  SolveCache own_cache;
  SolveOptions first = options;
  if (first.cache == nullptr) first.cache = &own_cache;
  body(0, first);
  // Four chunks keep two cores busy to the end whatever the chunks' costs; each chunk starts warm.
  constexpr std::size_t kChunks = 4;
  const std::size_t rest = count - 1;
  const std::size_t chunks = options.parallel_for ? std::min(kChunks, rest) : std::min<std::size_t>(1, rest);
  std::vector<SolveCache> caches(chunks, *first.cache);
  run_parallel(options.parallel_for, static_cast<int>(chunks), [&](int chunk) {
    SolveOptions one = options;
    one.cache = &caches[static_cast<std::size_t>(chunk)];
    one.parallel_for = {};
    for (std::size_t k = 1 + static_cast<std::size_t>(chunk); k < count; k += chunks) body(k, one);
  });
}

std::vector<LayerTables> solve_batch(std::span<const Material> materials, const SolveOptions& options) {
  std::vector<LayerTables> tables(materials.size());
  for_each_with_warm_cache(materials.size(), options,
                           [&](std::size_t k, const SolveOptions& one) { tables[k] = solve(materials[k], one); });
  return tables;
}

}  // namespace skinlayer
