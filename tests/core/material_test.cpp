#include "core/material.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace skinlayer {
namespace {

std::string error_of(const Material& material) {
  try {
    validate(material);
  } catch (const ParameterError& error) {
    return error.what();
  }
  return "";
}

TEST(Material, DefaultsAreThePapersSettings) {
  const Material m;
  EXPECT_EQ(m.sigma, 0.5);
  EXPECT_EQ(m.eta, 1.4);
  EXPECT_NEAR(m.transparency(), 0.2, 1e-15);
  EXPECT_EQ(m.albedo, 1.0);
  EXPECT_EQ(m.g, 0.8);
  EXPECT_EQ(m.bottom.kind, BottomKind::Air);
  EXPECT_EQ(m.bottom_eta(), 1.4);
  EXPECT_EQ(m.bottom_sigma(), 0.5);
  EXPECT_EQ(error_of(m), "");
  for (const ParameterInfo& info : parameter_table()) {
    if (info.flag == "T") {
      EXPECT_NEAR(info.default_value, m.transparency(), 1e-15);
    } else if (info.flag == "sigma") {
      EXPECT_EQ(info.default_value, m.sigma);
    } else if (info.flag == "g") {
      EXPECT_EQ(info.default_value, m.g);
    }
  }
}

TEST(Material, EveryOutOfRangeFieldIsNamedWithItsRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    const char* name;
    void (*set)(Material&, double);
    double bad;
  };
  const Case cases[] = {
      {"sigma", [](Material& m, double v) { m.sigma = v; }, 0.01},
      {"sigma", [](Material& m, double v) { m.sigma = v; }, nan},
      {"eta", [](Material& m, double v) { m.eta = v; }, 0.9},
      {"eta", [](Material& m, double v) { m.eta = v; }, 3.0},
      {"tau", [](Material& m, double v) { m.tau = v; }, -1.0},
      {"tau", [](Material& m, double v) { m.tau = v; }, nan},
      {"albedo", [](Material& m, double v) { m.albedo = v; }, 1.01},
      {"g", [](Material& m, double v) { m.g = v; }, 0.99},
      {"g", [](Material& m, double v) { m.g = v; }, -0.96},
      {"bottom-sigma", [](Material& m, double v) { m.bottom.sigma = v; }, 2.0},
      {"bottom-eta", [](Material& m, double v) { m.bottom.eta = v; }, 0.5},
      {"ordinates", [](Material& m, double v) { m.ordinates = static_cast<int>(v); }, 2.0},
      {"mu-t", [](Material& m, double v) { m.extinction = v; }, 0.0},
      {"mu-t", [](Material& m, double v) { m.extinction = v; }, -2.0},
      {"mu-t", [](Material& m, double v) { m.extinction = v; }, nan},
  };
  for (const Case& c : cases) {
    Material m;
    c.set(m, c.bad);
    const std::string message = error_of(m);
    EXPECT_NE(message.find(c.name), std::string::npos) << message;
    EXPECT_NE(message.find("valid range"), std::string::npos) << message;
  }
  Material lambert;
  lambert.bottom = {BottomKind::Lambert, {}, {}, 1.5};
  EXPECT_NE(error_of(lambert).find("lambert"), std::string::npos);
}

// A layer with an extinction coefficient has a length: tau / mu_t mm thick, 1 / mu_t mm per mean free path.
TEST(Material, ExtinctionGivesEachLayerItsThickness) {
  Material m;
  EXPECT_FALSE(mean_free_path_mm(m).has_value());
  EXPECT_FALSE(layer_thickness_mm(stack_layers(m)[0]).has_value());
  m.tau = 2.0;
  m.extinction = 20.0;  // 1/mm: a mean free path of 50 um, so tau 2 is 0.1 mm
  m.below = {StackedLayer{3.0, 0.9, 0.5, std::nullopt, 6.0},
             StackedLayer{std::numeric_limits<double>::infinity(), 0.9, 0.5, std::nullopt, 2.0}};
  EXPECT_EQ(error_of(m), "");
  EXPECT_DOUBLE_EQ(*mean_free_path_mm(m), 0.05);
  const std::vector<StackedLayer> layers = stack_layers(m);
  EXPECT_DOUBLE_EQ(*layer_thickness_mm(layers[0]), 0.1);
  EXPECT_DOUBLE_EQ(*layer_thickness_mm(layers[1]), 0.5);
  EXPECT_TRUE(std::isinf(*layer_thickness_mm(layers[2])));
  // A stacked layer's bad extinction is named with its place.
  m.below[0].extinction = -1.0;
  const std::string message = error_of(m);
  EXPECT_EQ(message.rfind("layer 2: mu-t = -1 is out of range; valid range is [1e-06, 1000000]", 0), 0u) << message;
}

TEST(Material, TransparencyMapsToOpticalDepth) {
  EXPECT_TRUE(std::isinf(optical_depth_from_transparency(0.0)));
  EXPECT_EQ(optical_depth_from_transparency(1.0), 0.0);
  EXPECT_NEAR(optical_depth_from_transparency(0.2), 1.6094379124341003, 1e-15);
  EXPECT_THROW(optical_depth_from_transparency(1.5), ParameterError);
}

TEST(Material, ParsesBottomSpecifications) {
  EXPECT_EQ(parse_bottom("air").kind, BottomKind::Air);
  EXPECT_EQ(parse_bottom("matched").kind, BottomKind::Matched);
  const Bottom bone = parse_bottom("lambert:0.25");
  EXPECT_EQ(bone.kind, BottomKind::Lambert);
  EXPECT_EQ(bone.lambert_albedo, 0.25);
  EXPECT_EQ(format_bottom(bone), "lambert:0.25");
  for (const char* bad : {"", "Air", "lambert", "lambert:", "lambert:x", "lambert:1.5", "lambert:0.5x", "bone"}) {
    EXPECT_THROW(parse_bottom(bad), ParameterError) << bad;
  }
}

}  // namespace
}  // namespace skinlayer
