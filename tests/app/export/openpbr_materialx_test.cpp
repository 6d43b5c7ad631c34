// `skinlayer export --format mtlx` checked against OpenPBR Surface's own node definition (tests/reference/openpbr,
// read with pugixml): every input known, of its type, within its range; the material names the shader; the fit's
// report and the material ride along and read back. The checker itself is shown to catch what it should. And
// MaterialX's own furnace, recorded (tests/reference/materialx_furnace.csv), is what skinlayer's OpenPBR model gives
// today's fits.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <sstream>
#include <string>

#include "tests/app/error_expectations.h"
#include "tests/app/export/materialx_nodedef.h"
#include "tests/app/process_runner.h"
#include "tests/app/scratch_folder.h"
#include "tests/core/reference_csv.h"

namespace skinlayer::test {
namespace {

const NodeDefinition& openpbr() {
  static const NodeDefinition definition = read_node_definition(
      std::string(SKINLAYER_REFERENCE_DIR) + "/openpbr/open_pbr_surface.mtlx", "ND_open_pbr_surface_surfaceshader");
  return definition;
}

class OpenPbrMaterialX : public ScratchFolderTest {
 protected:
  std::string exported(const std::vector<std::string>& material) {
    std::vector<std::string> arguments = {"export", "--format", "mtlx", "-o", path("m.mtlx")};
    arguments.insert(arguments.end(), material.begin(), material.end());
    const ProcessResult result = run_skinlayer(arguments);
    if (result.exit_code != 0) throw std::runtime_error(result.err);
    std::ifstream in(path("m.mtlx"));
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
};

// MaterialX's generated shader under a white environment (the figures materialx_validate.mjs prints where MaterialX's
// WebAssembly build is installed, recorded with their provenance in tests/reference/README.md) against the albedo
// skinlayer's model of OpenPBR gives each preset's fit at the same view: within 0.5% per channel, as MaterialX
// rendered it. A change of the model or of the fit that MaterialX would not follow fails here, in CI, without it.
TEST(OpenPbrMaterialXFurnace, TheRecordedRenderIsTheModelsAlbedoOfTodaysFit) {
  const CsvTable recorded = read_reference("materialx_furnace.csv");
  ASSERT_GE(recorded.rows.size(), 20u);
  std::map<std::string, nlohmann::json> fits;
  for (std::size_t row = 0; row < recorded.rows.size(); ++row) {
    const std::string preset = recorded.text(row, "preset");
    if (!fits.contains(preset)) {
      const ProcessResult fit = run_skinlayer({"fit", "--target", "openpbr", "--preset", preset});
      ASSERT_EQ(fit.exit_code, 0) << fit.err;
      fits[preset] = nlohmann::json::parse(fit.out);
    }
    const nlohmann::json& albedo = fits[preset].at("albedo");
    const double degrees = recorded.number(row, "theta_o_deg");
    bool found = false;
    for (std::size_t a = 0; a < albedo.at("degrees").size(); ++a) {
      if (std::abs(albedo.at("degrees")[a].get<double>() - degrees) > 1e-9) continue;
      found = true;
      const char* channels[] = {"materialx_r", "materialx_g", "materialx_b"};
      for (int c = 0; c < 3; ++c) {
        const double model = albedo.at("fitted")[a][c].get<double>();
        EXPECT_NEAR(recorded.number(row, channels[c]), model, 0.005 * model)
            << preset << " at " << degrees << " degrees, channel " << c;
      }
    }
    EXPECT_TRUE(found) << preset << ": the fit reports no albedo at " << degrees << " degrees";
  }
}

TEST(OpenPbrNodeDefinition, IsTheOneTheExportWritesFor) {
  EXPECT_EQ(openpbr().node, "open_pbr_surface");
  EXPECT_EQ(openpbr().output_type, "surfaceshader");
  EXPECT_EQ(openpbr().inputs.size(), 41u);
  EXPECT_EQ(openpbr().inputs.at("base_color").type, "color3");
  EXPECT_EQ(openpbr().inputs.at("specular_roughness").uimax->front(), 1.0);
}

TEST_F(OpenPbrMaterialX, EveryPresetsFileIsValidAgainstTheNodeDefinition) {
  for (const char* preset : {"skin-fair", "clear-coat-red", "jade", "paper-thin"}) {
    const std::string text = exported({"--preset", preset});
    const std::vector<std::string> problems = materialx_problems(text, openpbr(), "1.39");
    EXPECT_TRUE(problems.empty()) << preset << ": " << (problems.empty() ? "" : problems.front());
  }
}

TEST_F(OpenPbrMaterialX, CarriesTheFitAndTheMaterial) {
  const std::string text = exported({"--preset", "clear-coat-red"});
  pugi::xml_document xml;
  ASSERT_TRUE(xml.load_string(text.c_str()));
  const pugi::xml_node root = xml.child("materialx");
  const pugi::xml_node shader = root.child("open_pbr_surface");
  const std::string fit_doc = shader.attribute("doc").value();
  ASSERT_EQ(fit_doc.rfind("skinlayer fit ", 0), 0u);
  const nlohmann::json fit = nlohmann::json::parse(fit_doc.substr(14));
  EXPECT_EQ(fit.at("target"), "openpbr");
  // The inputs are the report's parameters.
  const ProcessResult direct = run_skinlayer({"fit", "--target", "openpbr", "--preset", "clear-coat-red"});
  ASSERT_EQ(direct.exit_code, 0);
  EXPECT_EQ(fit, nlohmann::json::parse(direct.out));
  const double coat_roughness =
      std::stod(shader.find_child_by_attribute("input", "name", "coat_roughness").attribute("value").value());
  EXPECT_EQ(coat_roughness, fit.at("parameters").at("coat_roughness").get<double>());
  const std::string material_doc = root.child("surfacematerial").attribute("doc").value();
  ASSERT_EQ(material_doc.rfind("skinlayer ", 0), 0u);
  const ProcessResult material = run_skinlayer({"material", "--preset", "clear-coat-red"});
  EXPECT_EQ(nlohmann::json::parse(material_doc.substr(10)), nlohmann::json::parse(material.out));
  EXPECT_EQ(std::string(root.child("surfacematerial").attribute("name").value()), "clear_coat_red");
}

// The radius says its unit with MaterialX's own attributes (the standard library's unit type "distance", whose unit
// "millimeter" is 0.001 m), so that a renderer that sets a target distance unit converts it; no other input has one.
TEST_F(OpenPbrMaterialX, TheRadiusCarriesItsUnitInMillimetres) {
  for (const char* preset : {"skin-fair", "clear-coat-red"}) {
    const std::string text = exported({"--preset", preset});
    pugi::xml_document xml;
    ASSERT_TRUE(xml.load_string(text.c_str()));
    const pugi::xml_node shader = xml.child("materialx").child("open_pbr_surface");
    int with_unit = 0;
    for (const pugi::xml_node in : shader.children("input")) {
      if (!in.attribute("unit")) continue;
      ++with_unit;
      EXPECT_EQ(std::string(in.attribute("name").value()), "subsurface_radius") << preset;
      EXPECT_EQ(std::string(in.attribute("unittype").value()), "distance") << preset;
      EXPECT_EQ(std::string(in.attribute("unit").value()), "millimeter") << preset;
    }
    EXPECT_EQ(with_unit, 1) << preset;
  }
  // skin-fair's radius is the dermis's mean free path, 0.026 mm: a number that only millimetres make right.
  const std::string skin = exported({"--preset", "skin-fair"});
  pugi::xml_document xml;
  ASSERT_TRUE(xml.load_string(skin.c_str()));
  const double radius = std::stod(xml.child("materialx")
                                      .child("open_pbr_surface")
                                      .find_child_by_attribute("input", "name", "subsurface_radius")
                                      .attribute("value")
                                      .value());
  EXPECT_NEAR(radius, 0.0255, 0.001);
}

// The checker fails a file with an unknown input, a wrong type, a value out of range, a bad value and a material
// that names no shader: it is not a check that passes anything.
TEST_F(OpenPbrMaterialX, TheCheckCatchesWhatIsWrong) {
  const std::string good = exported({"--preset", "wax"});
  ASSERT_TRUE(materialx_problems(good, openpbr(), "1.39").empty());
  const auto broken = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
  };
  const auto flagged = [&](const std::string& text, const std::string& fragment) {
    for (const std::string& problem : materialx_problems(text, openpbr(), "1.39")) {
      if (problem.find(fragment) != std::string::npos) return true;
    }
    return false;
  };
  EXPECT_TRUE(flagged(broken("name=\"fuzz_weight\"", "name=\"fuzz_wieght\""), "no such input"));
  EXPECT_TRUE(flagged(broken("name=\"base_color\" type=\"color3\"", "name=\"base_color\" type=\"float\""), "type"));
  EXPECT_TRUE(flagged(
      broken("name=\"coat_weight\" type=\"float\" value=\"0\"", "name=\"coat_weight\" type=\"float\" value=\"1.5\""),
      "above its uimax"));
  EXPECT_TRUE(flagged(
      broken("name=\"coat_weight\" type=\"float\" value=\"0\"", "name=\"coat_weight\" type=\"float\" value=\"zero\""),
      "is not a float"));
  EXPECT_TRUE(flagged(broken("nodename=\"SR_wax\"", "nodename=\"SR_other\""), "names no"));
  EXPECT_TRUE(flagged(broken("version=\"1.39\"", "version=\"1.38\""), "version"));
}

TEST_F(OpenPbrMaterialX, FlagsOfOtherFormatsAreOneLine) {
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"export", "--format", "mtlx", "--scene", "-o", path("x.mtlx")}), 2,
                                   {"--scene", "blender"}));
  EXPECT_TRUE(
      failed_with_one_line(run_skinlayer({"export", "--format", "mtlx", "--resolution", "32", "-o", path("x.mtlx")}), 2,
                           {"--resolution", "mtlx"}));
}

}  // namespace
}  // namespace skinlayer::test
