// The translucency's job on its thread (app/window/spread_job.h): one at a time, its outcome once, with the material
// it answers; a material without a profile is its one line. Also under ThreadSanitizer (ctest -L threads).
#include "app/window/spread_job.h"

#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <thread>

namespace skinlayer {
namespace {

SpreadOutcome wait_for(SpreadJob& job) {
  for (int i = 0; i < 6000; ++i) {
    if (std::optional<SpreadOutcome> outcome = job.take_outcome()) return *outcome;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ADD_FAILURE() << "the spread job did not end within 60 s";
  return {};
}

TEST(SpreadJob, OneAtATimeEachOutcomeOnceWithItsMaterial) {
  MaterialDocument half_space;  // a weakly absorbing half-space with lengths under a rough top
  half_space.layer.tau = std::numeric_limits<double>::infinity();
  half_space.layer.extinction = 5.0;
  half_space.layer.g = 0.8;
  half_space.albedo_rgb = {0.99, 0.95, 0.8};
  SpreadJob job;
  ASSERT_TRUE(job.start(half_space));
  EXPECT_FALSE(job.start(half_space));  // one at a time
  const SpreadOutcome outcome = wait_for(job);
  EXPECT_FALSE(job.running());
  EXPECT_EQ(outcome.document.layer.extinction, 5.0);
  ASSERT_TRUE(outcome.profile.has_value()) << outcome.why;
  ASSERT_EQ(outcome.profile->per_area.size(), 3u);
  EXPECT_GT(outcome.profile->per_area[0][10], outcome.profile->per_area[2][10] * 0.5);
  EXPECT_GT(outcome.profile->per_area[0][40], outcome.profile->per_area[2][40]);  // red reaches farthest
  EXPECT_FALSE(job.take_outcome().has_value());                                   // once

  MaterialDocument without_length = half_space;  // no mu_t: no sphere in mm
  without_length.layer.extinction.reset();
  ASSERT_TRUE(job.start(without_length));
  const SpreadOutcome refused = wait_for(job);
  EXPECT_FALSE(refused.profile.has_value());
  EXPECT_NE(refused.why.find("mu-t"), std::string::npos) << refused.why;
}

}  // namespace
}  // namespace skinlayer
