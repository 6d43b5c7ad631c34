// The GL textures of environments: one environment's maps (EnvironmentTextures), and the few that the renderer
// keeps after they were shown (KeptEnvironments), so that going back to one needs no upload.
//
// Keeping them is also what holds the previewer's memory flat: Debian 12's Mesa (llvmpipe, 22.3) kept the storage
// of environment textures that were specified anew or deleted, about 1 MB more with every change of environment in
// the previewer's soak (tests/app/window/window_soak_test.cpp; heaptrack: the allocations under glTexImage2D of
// the environment's maps still held at the end). Switching among kept environments specifies no texture.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "app/gl/gl_objects.h"
#include "app/render/environment_map.h"

namespace skinlayer {

// An environment's radiance (RGB32F, mipmapped for the blurred background, wrapping in u) and its luminance
// distribution for importance sampling (R32F, nearest): the density, the marginal CDF over rows and each row's
// conditional CDF (environment_map.h, EnvironmentDistribution). Units 4-7 of the sphere's programs.
struct EnvironmentTextures {
  gl::Texture radiance, density, marginal, conditional;
  int width = 0, height = 0;  // the map's texels
  std::size_t bytes = 0;      // the texels uploaded, mip levels included
};

// New texture objects holding `map`. Throws std::runtime_error for a black map (environment_distribution).
EnvironmentTextures upload_environment_textures(const EnvironmentMap& map);

// The shown environment and, least recently shown last, others kept while their bytes together stay within the
// budget. Keys name what was loaded (a built-in's name; a file's path with its size and time of change); the empty
// key is never found again.
class KeptEnvironments {
 public:
  static constexpr std::size_t kDefaultBudgetBytes = 48u << 20;  // besides the shown one: the built-ins take 16 MB

  explicit KeptEnvironments(std::size_t budget_bytes = kDefaultBudgetBytes) : budget_bytes_(budget_bytes) {}

  // Makes the kept environment `key` the shown one; false when none is kept under it.
  bool show(const std::string& key);
  // Makes `textures` the shown environment under `key`, dropping the least recently shown others over the budget.
  void add(std::string key, EnvironmentTextures textures);

  // The shown environment; add() must have been called once.
  const EnvironmentTextures& shown() const { return kept_.front().textures; }
  std::size_t count() const { return kept_.size(); }

 private:
  struct Entry {
    std::string key;
    EnvironmentTextures textures;
  };
  std::vector<Entry> kept_;  // the shown one first, then by the time they were last shown, latest first
  std::size_t budget_bytes_;
};

}  // namespace skinlayer
