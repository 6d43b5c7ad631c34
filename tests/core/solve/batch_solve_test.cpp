// A batch of solves sharing their interfaces (core/solve/batch_solve.h) must give each material's own solve,
// value for value: the warm caches hand out the operators a cold solve would build, and the chunks running side by
// side on threads change no arithmetic.
#include "core/solve/batch_solve.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/skin/skin_optics.h"
#include "core/solve/solve_cache.h"
#include "tests/core/two_threads.h"

namespace skinlayer {
namespace {

// Two threads, as the app's parallel-for gives on the 2-core machine.
using test::two_threads;

TEST(BatchSolve, EqualsOneSolvePerMaterial) {
  std::vector<Material> materials;
  SkinParameters skin;
  skin.blood = 0.02;
  for (const double wavelength : {420.0, 480.0, 542.0, 577.0, 610.0, 700.0}) {
    materials.push_back(skin_material(skin, wavelength));
  }
  SolveCache cache;
  SolveOptions options;
  options.cache = &cache;
  options.parallel_for = two_threads;
  const std::vector<LayerTables> batch = solve_batch(materials, options);
  ASSERT_EQ(batch.size(), materials.size());
  EXPECT_GT(cache.entries(), 0u);  // the caller's cache is warmed and kept
  for (std::size_t k = 0; k < materials.size(); ++k) {
    const LayerTables alone = solve(materials[k]);
    for (const double theta_i : {0.0, 0.4, 1.2}) {
      for (const double theta_o : {0.1, 0.7, 1.4}) {
        for (const double phi : {0.0, 1.0, 3.0}) {
          EXPECT_EQ(batch[k].brdf_subsurface(theta_i, theta_o, phi), alone.brdf_subsurface(theta_i, theta_o, phi))
              << "material " << k;
        }
      }
    }
  }
  EXPECT_TRUE(solve_batch(std::vector<Material>{}, options).empty());
}

}  // namespace
}  // namespace skinlayer
