// The environments the renderer keeps (app/render/environment_textures.h), through OSMesa:
//   * the textures' bytes are the texels uploaded, the radiance's mip chain included;
//   * others are kept within the budget, the least recently shown dropped first; one without a key goes as soon as
//     another is shown;
//   * an environment shown again from the kept ones lights the sphere exactly as one uploaded anew.
#include "app/render/environment_textures.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/gl/osmesa_context.h"
#include "app/render/environment_map.h"
#include "app/render/render_target.h"
#include "app/render/renderer.h"
#include "app/render/table_textures.h"
#include "app/solution/material_solve.h"

namespace skinlayer {
namespace {

constexpr int kSize = 96;

// A uniform 64 x 32 map: 64*32 RGB texels with their mip chain (4/3 of the base level: 32768 bytes), the density
// (8192), the marginal CDF (33 values) and the conditional CDFs (32 rows of 65).
EnvironmentMap small_map() { return EnvironmentMap{64, 32, std::vector<float>(64 * 32 * 3, 1.0f)}; }
constexpr std::size_t kSmallMapBytes = 32768 + 8192 + 33 * 4 + 32 * 65 * 4;

TEST(EnvironmentTextures, HoldTheTexelsUploadedWithTheRadiancesMipChain) {
  gl::OsmesaContext context{kSize, kSize};
  const EnvironmentTextures textures = upload_environment_textures(small_map());
  EXPECT_EQ(textures.width, 64);
  EXPECT_EQ(textures.height, 32);
  EXPECT_EQ(textures.bytes, kSmallMapBytes);
  EXPECT_NE(textures.radiance.get(), 0u);
  EXPECT_NE(textures.conditional.get(), 0u);
}

TEST(KeptEnvironments, KeepOthersWithinTheBudgetDroppingTheLeastRecentlyShownFirst) {
  gl::OsmesaContext context{kSize, kSize};
  KeptEnvironments kept(2 * kSmallMapBytes + kSmallMapBytes / 2);  // room for two besides the shown one
  for (const char* key : {"a", "b", "c", "d"}) kept.add(key, upload_environment_textures(small_map()));
  EXPECT_EQ(kept.count(), 3u);  // d shown; c and b kept; a dropped
  EXPECT_FALSE(kept.show("a"));
  EXPECT_TRUE(kept.show("b"));                              // b shown; d, then c
  kept.add("e", upload_environment_textures(small_map()));  // e shown; b, then d; c dropped
  EXPECT_FALSE(kept.show("c"));
  EXPECT_TRUE(kept.show("d"));
  EXPECT_TRUE(kept.show("b"));
  EXPECT_TRUE(kept.show("e"));
  EXPECT_EQ(kept.count(), 3u);
}

TEST(KeptEnvironments, OneWithoutAKeyGoesOnceAnotherIsShown) {
  gl::OsmesaContext context{kSize, kSize};
  KeptEnvironments kept;
  kept.add("", upload_environment_textures(small_map()));
  EXPECT_EQ(kept.count(), 1u);
  EXPECT_FALSE(kept.show(""));
  kept.add("b", upload_environment_textures(small_map()));
  EXPECT_EQ(kept.count(), 1u);
  kept.add("", upload_environment_textures(small_map()));
  EXPECT_EQ(kept.count(), 2u);  // the shown one without a key, and b
}

TEST(KeptEnvironments, AnEnvironmentShownAgainLightsTheSphereAsOneUploadedAnew) {
  gl::OsmesaContext context{kSize, kSize};
  const ColorTables tables = solve_color(ColorMaterial{}, 0.785);
  // The linear estimate of 16 samples per pixel under what `renderer` shows (the same sample sequence each time).
  const auto estimate = [&](const Renderer& renderer) {
    EnvironmentAccumulation accumulation(kSize, kSize);
    renderer.accumulate_environment(accumulation, EnvironmentView{}, SurfaceParams{}, 16);
    return accumulation.target().read_rgba32f();
  };
  Renderer fresh;
  fresh.upload(make_table_textures(tables));
  fresh.upload_environment(*builtin_environment("studio"));
  const std::vector<float> expected = estimate(fresh);

  Renderer renderer;
  renderer.upload(make_table_textures(tables));
  renderer.upload_environment(*builtin_environment("studio"), "studio");
  renderer.upload_environment(*builtin_environment("sky"), "sky");
  const std::vector<float> under_sky = estimate(renderer);
  ASSERT_TRUE(renderer.show_kept_environment("studio"));
  const std::vector<float> shown_again = estimate(renderer);
  ASSERT_EQ(shown_again.size(), expected.size());
  EXPECT_NE(under_sky, expected);  // the sky lights it differently: the comparison below can fail
  EXPECT_EQ(shown_again, expected);
  EXPECT_FALSE(renderer.show_kept_environment("forest"));
}

}  // namespace
}  // namespace skinlayer
