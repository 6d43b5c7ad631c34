// The stack seen from below (core/solve/upside_down.h): its construction, and the physics it must reproduce: a
// symmetric layer looks the same from both sides, and the BTDF from below is the BTDF from above through
// reciprocity, f(below -> above) = f(above -> below) (n_above / n_below)^2 (radiance BTDFs).
#include "core/solve/upside_down.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

Material three_layer_stack() {
  Material m;
  m.sigma = 0.3;
  m.eta = 1.3;
  m.tau = 0.5;
  m.albedo = 0.9;
  m.g = 0.6;
  m.below.push_back(StackedLayer{0.4, 0.8, 0.2, LayerInterface{0.4, 1.2}});
  m.below.push_back(StackedLayer{0.7, 0.95, -0.3, std::nullopt});
  m.bottom.sigma = 0.6;
  m.bottom.eta = 1.25;
  return m;
}

TEST(UpsideDown, ReversesTheLayersAndTurnsEachInterfaceAround) {
  const Material m = three_layer_stack();
  const std::optional<Material> f = upside_down(m);
  ASSERT_TRUE(f.has_value());
  EXPECT_NO_THROW(validate(*f));
  EXPECT_DOUBLE_EQ(f->eta, 1.25);  // the old bottom
  EXPECT_DOUBLE_EQ(f->sigma, 0.6);
  EXPECT_DOUBLE_EQ(f->tau, 0.7);
  EXPECT_DOUBLE_EQ(f->albedo, 0.95);
  EXPECT_DOUBLE_EQ(f->g, -0.3);
  ASSERT_EQ(f->below.size(), 2u);
  EXPECT_DOUBLE_EQ(f->below[0].tau, 0.4);
  EXPECT_FALSE(f->below[0].interface.has_value());  // none between the old layers 2 and 3
  EXPECT_DOUBLE_EQ(f->below[1].tau, 0.5);
  ASSERT_TRUE(f->below[1].interface.has_value());
  EXPECT_DOUBLE_EQ(f->below[1].interface->eta, 1.0 / 1.2);
  EXPECT_DOUBLE_EQ(f->below[1].interface->sigma, 0.4);
  EXPECT_EQ(f->bottom.kind, BottomKind::Air);
  EXPECT_DOUBLE_EQ(f->bottom_eta(), 1.3);  // the old top
  EXPECT_DOUBLE_EQ(f->bottom_sigma(), 0.3);
  // The same indices seen from the other side: n_below / n_above inverts.
  EXPECT_NEAR(index_below_over_above(*f) * index_below_over_above(m), 1.0, 1e-12);
  EXPECT_NEAR(index_below_over_above(m), 1.3 * 1.2 / 1.25, 1e-12);
}

TEST(UpsideDown, OpaqueMaterialsHaveNoViewFromBelowAndAMatchedBottomIsAnOpenTop) {
  Material lambert;
  lambert.bottom = parse_bottom("lambert:0.5");
  EXPECT_FALSE(upside_down(lambert).has_value());
  Material deep;
  deep.below.push_back(StackedLayer{std::numeric_limits<double>::infinity(), 0.9, 0.0, std::nullopt});
  EXPECT_FALSE(upside_down(deep).has_value());
  Material matched;
  matched.bottom.kind = BottomKind::Matched;
  const std::optional<Material> f = upside_down(matched);
  ASSERT_TRUE(f.has_value());
  EXPECT_DOUBLE_EQ(f->eta, 1.0);
  EXPECT_DOUBLE_EQ(index_below_over_above(matched), 1.4);
}

TEST(UpsideDown, ASymmetricLayerLooksTheSameFromBelow) {
  const Material skin;  // the same rough interface to air on both sides
  const LayerTables above = solve(skin);
  const LayerTables below = solve(*upside_down(skin));
  for (double ti : {0.1, 0.6, 1.2}) {
    for (double to : {0.2, 0.9}) {
      EXPECT_NEAR(below.brdf_subsurface(ti, to, 2.0), above.brdf_subsurface(ti, to, 2.0), 1e-12);
      EXPECT_NEAR(below.btdf(ti, to, 2.5), above.btdf(ti, to, 2.5), 1e-12);
    }
  }
}

TEST(UpsideDown, TheBtdfFromBelowIsTheReciprocalOfTheBtdfFromAbove) {
  const Material m = three_layer_stack();
  const LayerTables above = solve(m);
  const LayerTables below = solve(*upside_down(m));
  const double ratio = index_below_over_above(m);
  double peak = 0.0;
  for (double ti = 0.0; ti < 1.3; ti += 0.1)
    peak = std::max(peak, above.btdf(ti, std::asin(std::sin(ti) / ratio), kPi));
  ASSERT_GT(peak, 0.0);
  for (double a : {0.0, 0.35, 0.7, 1.0, 1.2}) {
    for (double b : {0.1, 0.5, 0.8, 1.1}) {
      for (double phi : {0.5, 2.0, kPi}) {
        // above: light from above at a, out the bottom at b; below: light from below at b, out the top at a.
        const double from_above = above.btdf(a, b, phi);
        const double from_below = below.btdf(b, a, phi);
        EXPECT_NEAR(from_below, from_above / (ratio * ratio), 0.01 * peak) << a << " " << b << " " << phi;
      }
    }
  }
}

}  // namespace
}  // namespace skinlayer
