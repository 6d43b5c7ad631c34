// A document's profile (app/solution/document_profile.h): each solve in its own mean free paths, mixed into the
// channels, and the progress it reports.
#include "app/solution/document_profile.h"

#include <gtest/gtest.h>

#include <limits>
#include <utility>
#include <vector>

namespace skinlayer {
namespace {

// An RGB half-space with its length: three solves, each reported once as it ends, in order; each channel is its
// albedo's grey profile.
TEST(DocumentProfile, ReportsEachSolveAndMixesTheChannels) {
  MaterialDocument document;
  document.layer.eta = 1.0;
  document.layer.bottom.kind = BottomKind::Matched;
  document.layer.tau = std::numeric_limits<double>::infinity();
  document.layer.g = 0.7;
  document.layer.extinction = 10.0;
  document.albedo_rgb = {0.95, 0.8, 0.5};
  ProfileRequest request;
  request.options.resolution = {8, 8};
  request.options.frequencies = 16;
  std::vector<std::pair<int, int>> reported;
  request.progress = [&](int done, int total) { reported.emplace_back(done, total); };
  const double radii[] = {0.05, 0.2};
  const DocumentProfile profile = document_profile_at_radii(document, radii, request);
  EXPECT_EQ(reported, (std::vector<std::pair<int, int>>{{1, 3}, {2, 3}, {3, 3}}));
  EXPECT_EQ(profile.unit, "mm");
  ASSERT_EQ(profile.reflectance.size(), 3u);
  for (int c = 0; c < 3; ++c) {
    MaterialDocument grey = document;
    grey.albedo_rgb = {document.albedo_rgb[c], document.albedo_rgb[c], document.albedo_rgb[c]};
    const DocumentProfile one = document_profile_at_radii(grey, radii, request);
    ASSERT_EQ(one.reflectance.size(), 1u);
    EXPECT_DOUBLE_EQ(profile.reflectance[c][0], one.reflectance[0][0]) << c;
    EXPECT_DOUBLE_EQ(profile.reflectance[c][1], one.reflectance[0][1]) << c;
  }
  EXPECT_GT(profile.reflectance[0][1], profile.reflectance[2][1]);  // the red albedo reaches farther
}

}  // namespace
}  // namespace skinlayer
