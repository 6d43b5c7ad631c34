// `skinlayer export --format blender` and `blender-3.4` read by Python itself: the script is Python that runs, with
// Blender's module stood in for by a mock of a given version, and the data it hands to Blender are the material (as
// `skinlayer material` writes it), the fit (as `skinlayer fit` writes it) and the node inputs from that fit; in the
// other node's Blender it stops. That Blender takes the inputs by those names and renders what skinlayer's model of
// its Principled BSDF predicts is blender_render_test.cpp's part.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>

#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"
#include "tests/app/scratch_folder.h"

namespace skinlayer::test {
namespace {

class BlenderScript : public ScratchFolderTest {};

// Runs the script under python3 with a mock `bpy` of Blender `version` ("4, 3, 2"), in the background (as `blender
// -b`), and returns its data as JSON; or the run itself, unparsed, through `run`.
ProcessResult run_script(const std::string& script, const std::string& version) {
  const std::string program =
      "import json, sys\n"
      "from unittest import mock\n"
      "bpy = mock.MagicMock()\n"
      "bpy.app.version = (" +
      version +
      ")\n"
      "bpy.app.version_string = '" +
      version +
      "'\n"
      "bpy.app.background = True\n"
      "sys.modules['bpy'] = bpy\n"
      "data = {}\n"
      "exec(open(sys.argv[1]).read(), data)\n"
      "print(json.dumps({key: data[key] for key in ('SKINLAYER_MATERIAL', 'SKINLAYER_FIT', 'PRINCIPLED_INPUTS',\n"
      "                  'MATERIAL_NAME', 'BUILD_SCENE', 'DISTRIBUTION')}))\n";
  return run_process({"python3", "-c", program, script});
}

nlohmann::json script_data(const std::string& script, const std::string& version) {
  const ProcessResult result = run_script(script, version);
  if (result.exit_code != 0) throw std::runtime_error("python3 could not run the script: " + result.err);
  return nlohmann::json::parse(result.out);
}

// Today's node: the inputs by Blender 4.x's socket names, the distribution the fit is made for.
TEST_F(BlenderScript, CarriesTheMaterialTheFitAndTheFittedInputs) {
  const std::string script = path("jade.py");
  const ProcessResult exported = run_skinlayer({"export", "--format", "blender", "--preset", "jade", "-o", script});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_NE(exported.out.find("Blender script"), std::string::npos) << exported.out;
  const nlohmann::json data = script_data(script, "4, 5, 0");

  const ProcessResult material = run_skinlayer({"material", "--preset", "jade"});
  ASSERT_EQ(material.exit_code, 0) << material.err;
  EXPECT_EQ(data.at("SKINLAYER_MATERIAL"), nlohmann::json::parse(material.out));
  const ProcessResult fit = run_skinlayer({"fit", "--target", "principled", "--preset", "jade"});
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const nlohmann::json fitted = nlohmann::json::parse(fit.out);
  EXPECT_EQ(data.at("SKINLAYER_FIT"), fitted);

  const nlohmann::json& inputs = data.at("PRINCIPLED_INPUTS");
  const nlohmann::json& parameters = fitted.at("parameters");
  for (const auto& [socket, key] : {std::pair{"Base Color", "base_color"}, std::pair{"Specular Tint", "specular_tint"},
                                    std::pair{"Coat Tint", "coat_tint"}, std::pair{"Sheen Tint", "sheen_tint"}}) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(inputs.at(socket).at(c), parameters.at(key).at(c)) << socket;
    EXPECT_EQ(inputs.at(socket).at(3), 1.0) << socket;
  }
  for (int c = 0; c < 3; ++c) EXPECT_EQ(inputs.at("Subsurface Radius").at(c), parameters.at("subsurface_radius").at(c));
  const std::pair<const char*, const char*> names[] = {{"Metallic", "metallic"},
                                                       {"Roughness", "roughness"},
                                                       {"IOR", "ior"},
                                                       {"Subsurface Weight", "subsurface_weight"},
                                                       {"Subsurface Scale", "subsurface_scale"},
                                                       {"Subsurface Anisotropy", "subsurface_anisotropy"},
                                                       {"Specular IOR Level", "specular_ior_level"},
                                                       {"Transmission Weight", "transmission_weight"},
                                                       {"Coat Weight", "coat_weight"},
                                                       {"Coat Roughness", "coat_roughness"},
                                                       {"Coat IOR", "coat_ior"},
                                                       {"Sheen Weight", "sheen_weight"},
                                                       {"Sheen Roughness", "sheen_roughness"}};
  for (const auto& [socket, key] : names) EXPECT_EQ(inputs.at(socket), parameters.at(key)) << socket;
  // Diffuse Roughness (4.3 and later) only where the fit uses it, so that 4.2 takes the rest.
  EXPECT_EQ(inputs.contains("Diffuse Roughness"), parameters.at("diffuse_roughness").get<double>() > 0.0);
  EXPECT_EQ(data.at("DISTRIBUTION"), parameters.at("distribution"));
  EXPECT_EQ(data.at("MATERIAL_NAME"), "skinlayer jade");
  EXPECT_EQ(data.at("BUILD_SCENE"), false);
}

// Blender 3.4's node: its own socket names, distribution GGX.
TEST_F(BlenderScript, TheBlender34ScriptCarriesItsOwnInputs) {
  const std::string script = path("jade.py");
  ASSERT_EQ(run_skinlayer({"export", "--format", "blender-3.4", "--preset", "jade", "-o", script}).exit_code, 0);
  const nlohmann::json data = script_data(script, "3, 4, 1");
  const ProcessResult fit = run_skinlayer({"fit", "--target", "principled-3.4", "--preset", "jade"});
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const nlohmann::json fitted = nlohmann::json::parse(fit.out);
  EXPECT_EQ(data.at("SKINLAYER_FIT"), fitted);
  const nlohmann::json& inputs = data.at("PRINCIPLED_INPUTS");
  const nlohmann::json& parameters = fitted.at("parameters");
  for (int c = 0; c < 3; ++c) EXPECT_EQ(inputs.at("Base Color").at(c), parameters.at("base_color").at(c));
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
  EXPECT_EQ(data.at("DISTRIBUTION"), "GGX");
}

// Each script in the other node's Blender stops, before it builds anything, with one line that names the export to
// make; under `blender -b` with status 1 (SystemExit), so that nothing renders.
TEST_F(BlenderScript, InTheOtherNodesBlenderItStopsWithOneLine) {
  const std::string today = path("today.py"), old = path("old.py");
  ASSERT_EQ(run_skinlayer({"export", "--format", "blender", "--preset", "wax", "-o", today}).exit_code, 0);
  ASSERT_EQ(run_skinlayer({"export", "--format", "blender-3.4", "--preset", "wax", "-o", old}).exit_code, 0);
  for (const auto& [script, version, other] :
       {std::tuple{today, "3, 4, 1", "--format blender-3.4"}, std::tuple{today, "4, 1, 0", "Blender 4.2 or later"},
        std::tuple{old, "4, 3, 2", "--format blender`"}, std::tuple{old, "5, 2, 2", "--format blender`"}}) {
    const ProcessResult result = run_script(script, version);
    EXPECT_EQ(result.exit_code, 1) << version << ": " << result.out << result.err;
    EXPECT_EQ(result.out, "") << version;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(other), std::string::npos) << result.err;
  }
  EXPECT_EQ(run_script(today, "4, 2, 0").exit_code, 0);  // wax's fit leaves Diffuse Roughness at 0
  // Jade's uses it, which Blender 4.3 added: in 4.2 the script asks for 4.3, not for the other export.
  const std::string jade = path("jade.py");
  ASSERT_EQ(run_skinlayer({"export", "--format", "blender", "--preset", "jade", "-o", jade}).exit_code, 0);
  const ProcessResult too_old = run_script(jade, "4, 2, 0");
  EXPECT_EQ(too_old.exit_code, 1);
  EXPECT_NE(too_old.err.find("Blender 4.3 or later"), std::string::npos) << too_old.err;
  EXPECT_EQ(run_script(jade, "4, 3, 0").exit_code, 0);
  EXPECT_EQ(run_script(today, "5, 2, 2").exit_code, 0);
  EXPECT_EQ(run_script(old, "3, 6, 0").exit_code, 0);
}

TEST_F(BlenderScript, SceneIsAsked) {
  const std::string script = path("wax.py");
  ASSERT_EQ(run_skinlayer({"export", "--format", "blender", "--scene", "--preset", "wax", "-o", script}).exit_code, 0);
  EXPECT_EQ(script_data(script, "4, 3, 2").at("BUILD_SCENE"), true);
}

TEST_F(BlenderScript, FlagsOfOtherFormatsAreOneLine) {
  const std::string script = path("x.py");
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"export", "--format", "blender", "--nodes", "9", "-o", script}), 2,
                                   {"--nodes", "blender"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"export", "--format", "blender", "--rgb", "-o", script}), 2,
                                   {"--rgb", "blender"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"export", "--format", "rgl", "--scene", "-o", script}), 2,
                                   {"--scene", "blender", "blender-3.4"}));
  EXPECT_TRUE(
      failed_with_one_line(run_skinlayer({"export", "--format", "blend", "-o", script}), 2, {"'blend'", "blender"}));
  EXPECT_FALSE(std::filesystem::exists(script));
}

}  // namespace
}  // namespace skinlayer::test
