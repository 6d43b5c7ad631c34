// CIEDE2000 against the supplementary test data of Sharma, Wu & Dalal 2005 (their Table 1: pairs chosen to
// exercise the hue-angle wrap-around, the mean-hue branches and the rotation term), and CIELAB's anchors.
#include "core/color/ciede2000.h"

#include <gtest/gtest.h>

namespace skinlayer {
namespace {

TEST(Ciede2000, ReproducesSharmasTestPairs) {
  struct Pair {
    double l1, a1, b1, l2, a2, b2, expected;
  };
  const Pair pairs[] = {
      {50.0000, 2.6772, -79.7751, 50.0000, 0.0000, -82.7485, 2.0425},    // 1
      {50.0000, 3.1571, -77.2803, 50.0000, 0.0000, -82.7485, 2.8615},    // 2
      {50.0000, 2.8361, -74.0200, 50.0000, 0.0000, -82.7485, 3.4412},    // 3
      {50.0000, -1.3802, -84.2814, 50.0000, 0.0000, -82.7485, 1.0000},   // 4
      {50.0000, 0.0000, 0.0000, 50.0000, -1.0000, 2.0000, 2.3669},       // 7
      {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0009, 7.1792},      // 9
      {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0011, 7.2195},      // 11
      {50.0000, -0.0010, 2.4900, 50.0000, 0.0009, -2.4900, 4.8045},      // 13
      {50.0000, 2.5000, 0.0000, 73.0000, 25.0000, -18.0000, 27.1492},    // 17
      {50.0000, 2.5000, 0.0000, 61.0000, -5.0000, 29.0000, 22.8977},     // 18
      {60.2574, -34.0099, 36.2677, 60.4626, -34.1751, 39.4387, 1.2644},  // 25
  };
  for (const Pair& p : pairs) {
    const Eigen::Vector3d lab1(p.l1, p.a1, p.b1), lab2(p.l2, p.a2, p.b2);
    EXPECT_NEAR(ciede2000(lab1, lab2), p.expected, 1e-4) << p.l1 << " " << p.a1 << " " << p.b1;
    EXPECT_NEAR(ciede2000(lab2, lab1), p.expected, 1e-4);  // symmetric
  }
  EXPECT_EQ(ciede2000(Eigen::Vector3d(40, 10, -20), Eigen::Vector3d(40, 10, -20)), 0.0);
}

TEST(Ciede2000, WhiteIsLightnessHundredAndGreyHasNoChroma) {
  const Eigen::Vector3d white = linear_srgb_to_lab(Eigen::Vector3d(1, 1, 1));
  EXPECT_NEAR(white.x(), 100.0, 1e-9);
  EXPECT_NEAR(white.y(), 0.0, 1e-9);
  EXPECT_NEAR(white.z(), 0.0, 1e-9);
  const Eigen::Vector3d grey = linear_srgb_to_lab(Eigen::Vector3d(0.18, 0.18, 0.18));
  EXPECT_NEAR(grey.x(), 49.496, 1e-3);  // 116 * 0.18^(1/3) - 16
  EXPECT_NEAR(grey.y(), 0.0, 1e-9);
  EXPECT_NEAR(linear_srgb_to_lab(Eigen::Vector3d(0, 0, 0)).x(), 0.0, 1e-12);
}

}  // namespace
}  // namespace skinlayer
