// The layers panel's edits (app/preview/layer_stack.h): every result is a valid stack, values travel with their
// layer, and one layer round-trips unchanged.
#include "app/preview/layer_stack.h"

#include <gtest/gtest.h>

#include <cmath>

namespace skinlayer {
namespace {

ColorMaterial skin() {
  ColorMaterial m;
  m.layer.tau = 0.5;
  m.layer.g = 0.8;
  m.albedo_rgb = {0.98, 0.94, 0.86};
  m.layer.below = {{INFINITY, 0.995, 0.7, std::nullopt}};
  m.below_rgb = {{0.995, 0.9, 0.84}};
  return m;
}

TEST(LayerStack, OneLayerRoundTripsUnchanged) {
  ColorMaterial one;
  one.albedo_rgb = {0.9, 0.5, 0.2};
  ColorMaterial copy = one;
  set_layers(copy, editable_layers(one));
  EXPECT_TRUE(differ_only_in_albedos(copy.layer, one.layer));  // layer.albedo is not used: albedo_rgb is
  EXPECT_EQ(copy.albedo_rgb, one.albedo_rgb);
  EXPECT_TRUE(copy.below_rgb.empty());
}

TEST(LayerStack, AddingUnderASemiInfiniteLayerKeepsItAtTheBottom) {
  ColorMaterial m = skin();
  m.model = SubsurfaceModel::HanrahanKrueger;
  add_layer(m);
  ASSERT_EQ(m.layer.layer_count(), 3);
  EXPECT_TRUE(std::isinf(m.layer.below.back().tau));
  EXPECT_EQ(m.layer.below[0].tau, kUnburiedDepth);
  EXPECT_EQ(m.below_rgb[0], (AlbedoRgb{0.995, 0.9, 0.84})) << "the copy keeps the last layer's colour";
  EXPECT_EQ(m.model, SubsurfaceModel::Stam);
  EXPECT_NO_THROW(validate(m.layer));
  // Under a finite last layer the copy goes below it.
  ColorMaterial finite;
  add_layer(finite);
  EXPECT_EQ(finite.layer.layer_count(), 2);
  EXPECT_EQ(finite.layer.below[0].tau, finite.layer.tau);
}

TEST(LayerStack, MovesCarryTheInterfaceAndNeverBuryASemiInfiniteLayer) {
  ColorMaterial m = skin();
  add_layer(m);  // 0.5 | 0.693 | inf
  m.layer.below[0].interface = LayerInterface{0.3, 1.2};
  EXPECT_FALSE(can_move(m, 2, -1)) << "the semi-infinite layer would be buried";
  EXPECT_FALSE(can_move(m, 1, +1));
  EXPECT_FALSE(can_move(m, 0, -1));
  EXPECT_TRUE(can_move(m, 1, -1));
  move_layer(m, 1, -1);  // the layer with the interface goes to the top, where the top interface is
  EXPECT_EQ(m.layer.tau, kUnburiedDepth);
  EXPECT_FALSE(m.layer.below[0].interface.has_value());
  EXPECT_EQ(m.albedo_rgb, (AlbedoRgb{0.995, 0.9, 0.84}));
  EXPECT_EQ(m.below_rgb[0], (AlbedoRgb{0.98, 0.94, 0.86}));
  EXPECT_NO_THROW(validate(m.layer));
  move_layer(m, 2, -1);  // refused: nothing changes
  EXPECT_TRUE(std::isinf(m.layer.below.back().tau));
}

TEST(LayerStack, RemovingKeepsAtLeastOneLayer) {
  ColorMaterial m = skin();
  remove_layer(m, 0);
  EXPECT_EQ(m.layer.layer_count(), 1);
  EXPECT_TRUE(std::isinf(m.layer.tau));
  EXPECT_EQ(m.albedo_rgb, (AlbedoRgb{0.995, 0.9, 0.84}));
  remove_layer(m, 0);
  EXPECT_EQ(m.layer.layer_count(), 1);
}

}  // namespace
}  // namespace skinlayer
