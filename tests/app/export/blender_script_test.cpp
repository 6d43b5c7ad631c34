// `skinlayer export --format blender` read by Python itself: the script is Python that runs, with Blender's module
// stood in for by a mock, and the data it hands to Blender are the material (as `skinlayer material` writes it),
// the fit (as `skinlayer fit` writes it) and the node inputs from that fit. That Blender takes the inputs by those
// names and renders what skinlayer's Principled BSDF predicts is blender_render_test.cpp's part.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"
#include "tests/app/scratch_folder.h"

namespace skinlayer::test {
namespace {

class BlenderScript : public ScratchFolderTest {};

// Runs the script under python3 with a mock `bpy`, and returns its data as JSON.
nlohmann::json script_data(const std::string& script) {
  const std::string program =
      "import json, sys\n"
      "from unittest import mock\n"
      "sys.modules['bpy'] = mock.MagicMock()\n"
      "data = {}\n"
      "exec(open(sys.argv[1]).read(), data)\n"
      "print(json.dumps({key: data[key] for key in ('SKINLAYER_MATERIAL', 'SKINLAYER_FIT', 'PRINCIPLED_INPUTS',\n"
      "                  'MATERIAL_NAME', 'BUILD_SCENE')}))\n";
  const ProcessResult result = run_process({"python3", "-c", program, script});
  if (result.exit_code != 0) throw std::runtime_error("python3 could not run the script: " + result.err);
  return nlohmann::json::parse(result.out);
}

TEST_F(BlenderScript, CarriesTheMaterialTheFitAndTheFittedInputs) {
  const std::string script = path("jade.py");
  const ProcessResult exported = run_skinlayer({"export", "--format", "blender", "--preset", "jade", "-o", script});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.out.find("Blender script"), std::string::npos) << exported.out;
  const nlohmann::json data = script_data(script);

  const ProcessResult material = run_skinlayer({"material", "--preset", "jade"});
  ASSERT_EQ(material.exit_code, 0) << material.err;
  EXPECT_EQ(data.at("SKINLAYER_MATERIAL"), nlohmann::json::parse(material.out));
  const ProcessResult fit = run_skinlayer({"fit", "--target", "principled", "--preset", "jade"});
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const nlohmann::json fitted = nlohmann::json::parse(fit.out);
  EXPECT_EQ(data.at("SKINLAYER_FIT"), fitted);

  const nlohmann::json& inputs = data.at("PRINCIPLED_INPUTS");
  const nlohmann::json& parameters = fitted.at("parameters");
  for (int c = 0; c < 3; ++c) EXPECT_EQ(inputs.at("Base Color").at(c), parameters.at("base_color").at(c));
  EXPECT_EQ(inputs.at("Base Color").at(3), 1.0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(inputs.at("Subsurface Color").at(c), parameters.at("subsurface_color").at(c));
    EXPECT_EQ(inputs.at("Subsurface Radius").at(c), parameters.at("subsurface_radius").at(c));
  }
  const std::pair<const char*, const char*> names[] = {{"Metallic", "metallic"},
                                                       {"Specular", "specular"},
                                                       {"Specular Tint", "specular_tint"},
                                                       {"Roughness", "roughness"},
                                                       {"Sheen", "sheen"},
                                                       {"Sheen Tint", "sheen_tint"},
                                                       {"Clearcoat", "clearcoat"},
                                                       {"Clearcoat Roughness", "clearcoat_roughness"},
                                                       {"Transmission", "transmission"},
                                                       {"Subsurface", "subsurface"}};
  for (const auto& [socket, key] : names) EXPECT_EQ(inputs.at(socket), parameters.at(key)) << socket;
  EXPECT_EQ(data.at("MATERIAL_NAME"), "skinlayer jade");
  EXPECT_EQ(data.at("BUILD_SCENE"), false);
}

TEST_F(BlenderScript, SceneIsAsked) {
  const std::string script = path("wax.py");
  ASSERT_EQ(run_skinlayer({"export", "--format", "blender", "--scene", "--preset", "wax", "-o", script}).exit_code, 0);
  EXPECT_EQ(script_data(script).at("BUILD_SCENE"), true);
}

TEST_F(BlenderScript, FlagsOfOtherFormatsAreOneLine) {
  const std::string script = path("x.py");
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"export", "--format", "blender", "--nodes", "9", "-o", script}), 2,
                                   {"--nodes", "blender"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"export", "--format", "blender", "--rgb", "-o", script}), 2,
                                   {"--rgb", "blender"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"export", "--format", "rgl", "--scene", "-o", script}), 2,
                                   {"--scene", "blender"}));
  EXPECT_TRUE(
      failed_with_one_line(run_skinlayer({"export", "--format", "blend", "-o", script}), 2, {"'blend'", "blender"}));
  EXPECT_FALSE(std::filesystem::exists(script));
}

}  // namespace
}  // namespace skinlayer::test
