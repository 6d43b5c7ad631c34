// The previewer's test hook for edits of its state (app/preview/scripted_edit.h), without a window: what each
// action changes, the steps of a drag, and one clear line for a malformed action.
#include "app/preview/scripted_edit.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace skinlayer {
namespace {

std::string error_of(PreviewState& state, std::string_view verb, std::string_view argument) {
  try {
    apply_scripted_edit(state, verb, argument);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

TEST(ScriptedEdit, SetsSlidersLayersLightingAndTheSplit) {
  PreviewState state;
  EXPECT_TRUE(apply_scripted_edit(state, "set", "sigma 0.25"));
  EXPECT_EQ(state.material.layer.sigma, 0.25);
  EXPECT_TRUE(apply_scripted_edit(state, "set", "albedo 0.5"));
  EXPECT_EQ(state.material.albedo_rgb, (AlbedoRgb{0.5, 0.5, 0.5}));
  EXPECT_TRUE(apply_scripted_edit(state, "layer", "add"));
  EXPECT_EQ(state.material.layer.layer_count(), 2);
  EXPECT_TRUE(apply_scripted_edit(state, "layer", "remove 7")) << "past the last layer: the button does nothing";
  EXPECT_EQ(state.material.layer.layer_count(), 2);
  EXPECT_TRUE(apply_scripted_edit(state, "layer", "remove 2"));
  EXPECT_EQ(state.material.layer.layer_count(), 1);
  EXPECT_TRUE(apply_scripted_edit(state, "lighting", "env sky"));
  EXPECT_EQ(state.lighting.environment, "sky");
  EXPECT_TRUE(apply_scripted_edit(state, "lighting", "env none"));
  EXPECT_EQ(state.lighting.environment, "");
  EXPECT_TRUE(apply_scripted_edit(state, "split", "0.3"));
  EXPECT_EQ(state.comparison.split, 0.3);
  EXPECT_FALSE(apply_scripted_edit(state, "undo", "")) << "the window's own actions are not edits of the state";
}

TEST(ScriptedEdit, ADragIsItsValuesInOrder) {
  EXPECT_EQ(drag_steps("g 0.1,0.2,0.35"), (std::vector<std::string>{"g 0.1", "g 0.2", "g 0.35"}));
  EXPECT_THROW(drag_steps("g"), std::runtime_error);
  EXPECT_THROW(drag_steps("g 0.1,x"), std::runtime_error);
}

TEST(ScriptedEdit, AMalformedNumberIsOneLineNamingIt) {
  PreviewState state;
  EXPECT_EQ(error_of(state, "set", "sigma"), "test action: sigma = '' is not a number");
  EXPECT_EQ(error_of(state, "split", "half"), "test action: split = 'half' is not a number");
  EXPECT_EQ(error_of(state, "lighting", "env-ev 1e999"),
            "test action: env-ev = '1e999' is too large for a double (magnitude above 1.8e308)");
  EXPECT_EQ(error_of(state, "layer", "up x"), "test action: layer = 'x' is not a number");
  EXPECT_EQ(error_of(state, "layer", "sideways 1"), "test action: unknown layer action 'sideways'");
}

// "view": the light's sliders, the sphere's radius and the translucency (issue 43).
TEST(ScriptedEdit, ViewSetsTheLightTheRadiusAndTheTranslucency) {
  PreviewState state;
  EXPECT_TRUE(apply_scripted_edit(state, "view", "light-theta 80"));
  EXPECT_TRUE(apply_scripted_edit(state, "view", "light-phi -30"));
  EXPECT_TRUE(apply_scripted_edit(state, "view", "radius 12.5"));
  EXPECT_TRUE(apply_scripted_edit(state, "view", "translucency off"));
  EXPECT_EQ(state.light.theta_degrees, 80.0);
  EXPECT_EQ(state.light.phi_degrees, -30.0);
  EXPECT_EQ(state.view.sphere_radius_mm, 12.5);
  EXPECT_FALSE(state.view.translucency);
  EXPECT_THROW(apply_scripted_edit(state, "view", "zoom 2"), std::runtime_error);
  EXPECT_THROW(apply_scripted_edit(state, "view", "radius big"), std::runtime_error);
}

}  // namespace
}  // namespace skinlayer
