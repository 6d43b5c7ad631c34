// OpenPBR's fuzz (docs/model.md §22.3): the LTC is a density over the light's hemisphere, so the lobe's albedo at
// each view is its fitted E, which stays a fraction.
#include "core/targets/zeltner_fuzz.h"

#include <gtest/gtest.h>

#include "tests/core/targets/hemisphere_integral.h"

namespace skinlayer {
namespace {

using test::expect_lobe_integrates_to_its_albedo;

TEST(ZeltnerFuzz, TheLobeIntegratesToItsAlbedoAtEveryView) {
  expect_lobe_integrates_to_its_albedo(zeltner_fuzz_cosine_weighted, zeltner_fuzz_albedo, 1e-12);
}

}  // namespace
}  // namespace skinlayer
