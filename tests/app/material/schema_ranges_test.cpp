// The JSON Schema (app/material/material.schema.json) states the parameters' ranges for other tools; they must be
// core's parameter table's, or the schema and the reader drift apart.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/material.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer {
namespace {

TEST(MaterialSchema, RangesAreCoresParameterTable) {
  std::ifstream file(SKINLAYER_MATERIAL_SCHEMA);
  ASSERT_TRUE(file) << SKINLAYER_MATERIAL_SCHEMA;
  const nlohmann::json schema = nlohmann::json::parse(file);
  const auto expect_range = [](const nlohmann::json& property, std::string_view flag) {
    const ParameterInfo& info = parameter_info(flag);
    EXPECT_EQ(property["minimum"].get<double>(), info.min) << flag;
    if (std::isfinite(info.max)) {
      EXPECT_EQ(property["maximum"].get<double>(), info.max) << flag;
    }
  };
  const nlohmann::json& top = schema["properties"]["top"]["properties"];
  expect_range(top["sigma"], "sigma");
  expect_range(top["eta"], "eta");
  const nlohmann::json& layer = schema["$defs"]["layer"]["properties"];
  expect_range(layer["T"], "T");
  expect_range(layer["tau"]["oneOf"][0], "tau");
  expect_range(schema["$defs"]["albedo"], "albedo");
  expect_range(layer["g"], "g");
  expect_range(layer["mu_t"], "mu-t");
  const nlohmann::json& air = schema["properties"]["bottom"]["oneOf"][0]["properties"];
  expect_range(air["sigma"], "bottom-sigma");
  expect_range(air["eta"], "bottom-eta");
  expect_range(schema["properties"]["bottom"]["oneOf"][2]["properties"]["albedo"], "lambert");
  expect_range(schema["properties"]["ordinates"], "ordinates");
  const nlohmann::json& skin = schema["properties"]["skin"]["properties"];
  EXPECT_EQ(skin.size(), skin_parameter_table().size());
  for (const ParameterInfo& info : skin_parameter_table()) {
    const nlohmann::json& property = skin[std::string(info.flag)];
    EXPECT_EQ(property["minimum"].get<double>(), info.min) << info.flag;
    EXPECT_EQ(property["maximum"].get<double>(), info.max) << info.flag;
  }
}

}  // namespace
}  // namespace skinlayer
