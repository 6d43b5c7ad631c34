// Materials that last (issue 11), on the real executable: `material` writes what --material reads back bit for bit,
// a rendered PNG carries its material, flags override a file, `presets` lists them, and every failure is one line
// with exit status 2 (1 for an unwritable output) that leaves no file behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"
#include "tests/app/scratch_folder.h"

namespace skinlayer::test {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kRows = "theta_i,theta_o,phi\n0,0,0\n30,25,180\n60,70,90\n80,10,0\n45,45,180\n";

// A fresh folder for one test, removed afterwards, and what it holds.
class MaterialCommands : public ScratchFolderTest {
 protected:
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
    return names;
  }
};

ProcessResult eval_with(std::vector<std::string> flags) {
  flags.insert(flags.begin(), "eval");
  return run_skinlayer(flags, kRows);
}

TEST_F(MaterialCommands, AWrittenMaterialEvaluatesBitForBitLikeItsFlags) {
  const std::vector<std::vector<std::string>> materials = {
      {},
      {"--sigma", "0.3", "--T", "0.1", "--albedo", "0.9", "--g", "0.5", "--bottom", "lambert:0.3"},
      {"--eta", "1.2", "--tau", "0.1", "--bottom", "air", "--bottom-sigma", "0.2", "--bottom-eta", "1.1"},
      {"--T", "0", "--albedo", "0.7", "--bottom", "matched", "--model", "hk"},
  };
  for (const std::vector<std::string>& flags : materials) {
    std::vector<std::string> write = {"material", "-o", path("m.json")};
    write.insert(write.end(), flags.begin(), flags.end());
    const ProcessResult written = run_skinlayer(write);
    ASSERT_EQ(written.exit_code, 0) << written.err;
    EXPECT_TRUE(written.out.empty()) << "with -o nothing goes to stdout";
    const ProcessResult direct = eval_with(flags);
    const ProcessResult from_file = eval_with({"--material", path("m.json")});
    ASSERT_EQ(direct.exit_code, 0) << direct.err;
    ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
    EXPECT_EQ(from_file.out, direct.out) << "flags: " << ::testing::PrintToString(flags);
    std::vector<std::string> albedo = {"albedo", "--theta-i", "0,45"};
    albedo.insert(albedo.end(), flags.begin(), flags.end());
    const std::vector<std::string> model_free(albedo.begin(), std::find(albedo.begin(), albedo.end(), "--model"));
    EXPECT_EQ(run_skinlayer({"albedo", "--theta-i", "0,45", "--material", path("m.json")}).out,
              run_skinlayer(model_free).out)
        << "albedo reads the file too";
    // And to stdout: the same file.
    std::vector<std::string> print = {"material"};
    print.insert(print.end(), flags.begin(), flags.end());
    std::ifstream file(path("m.json"));
    const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    EXPECT_EQ(run_skinlayer(print).out, text);
  }
}

TEST_F(MaterialCommands, FlagsGivenNextToAFileOverrideItsValues) {
  ASSERT_EQ(run_skinlayer({"material", "--sigma", "0.3", "--g", "0.5", "-o", path("m.json")}).exit_code, 0);
  const ProcessResult overridden = eval_with({"--material", path("m.json"), "--g", "0.2"});
  const ProcessResult direct = eval_with({"--sigma", "0.3", "--g", "0.2", "--bottom-sigma", "0.3"});
  ASSERT_EQ(overridden.exit_code, 0) << overridden.err;
  EXPECT_EQ(overridden.out, direct.out) << "the file's sigma 0.3 (top and its explicit bottom), the flag's g";
  // A preset, with a grey albedo over its RGB one, and a different top roughness.
  const ProcessResult preset = eval_with({"--preset", "paper-skin", "--albedo", "0.5", "--sigma", "0.2"});
  const ProcessResult spelled =
      eval_with({"--sigma", "0.2", "--eta", "1.4", "--T", "0.05", "--albedo", "0.5", "--g", "0.8", "--bottom-sigma",
                 "0.35", "--bottom-eta", "1.4", "--microfacet", "single"});  // a paper-* preset: Stam's interfaces
  ASSERT_EQ(preset.exit_code, 0) << preset.err;
  EXPECT_EQ(preset.out, spelled.out);
}

TEST_F(MaterialCommands, ARenderedPngCarriesItsMaterial) {
  const std::vector<std::string> flags = {"--sigma",  "0.3", "--T",      "0.05",
                                          "--albedo", "0.8", "--bottom", "lambert:0.4"};
  std::vector<std::string> render = {"render", "--size", "48x48", "--view", "sphere", "-o", path("shot.png")};
  render.insert(render.end(), flags.begin(), flags.end());
  const ProcessResult rendered = run_skinlayer(render);
  ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
  const ProcessResult from_png = eval_with({"--material", path("shot.png")});
  ASSERT_EQ(from_png.exit_code, 0) << from_png.err;
  EXPECT_EQ(from_png.out, eval_with(flags).out);
  // An RGB picture reads back into `material` with its three channels and the settings it was drawn with.
  ASSERT_EQ(run_skinlayer(
                {"render", "--size", "32x32", "--preset", "paper-skin", "--light-theta", "30", "-o", path("rgb.png")})
                .exit_code,
            0);
  const ProcessResult material = run_skinlayer({"material", "--material", path("rgb.png")});
  ASSERT_EQ(material.exit_code, 0) << material.err;
  EXPECT_NE(material.out.find("\"name\": \"paper-skin\""), std::string::npos) << material.out;
  EXPECT_NE(material.out.find("0.55"), std::string::npos) << material.out;
}

TEST_F(MaterialCommands, PresetsListsNameAndDescription) {
  const ProcessResult result = run_skinlayer({"presets"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* name : {"paper-default", "skin-fair", "skin-medium", "skin-dark", "leaf", "wax", "jade"}) {
    EXPECT_NE(result.out.find(std::string(name) + " "), std::string::npos) << name;
  }
  EXPECT_NE(result.out.find("a look, not a measurement"), std::string::npos);
}

// `presets --colors`: one row per preset, its colour at normal incidence as `albedo` computes it; under the
// interfaces that keep their light no rough preset is darker than under Stam's, in any channel.
std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::stringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::stringstream row(line);
    std::string field;
    while (std::getline(row, field, ',')) fields.push_back(field);
    rows.push_back(fields);
  }
  return rows;
}

TEST_F(MaterialCommands, PresetColorsAreTheirAlbedoAndTheKeptLightNeverDarkensThem) {
  const ProcessResult own = run_skinlayer({"presets", "--colors"});
  const ProcessResult single = run_skinlayer({"presets", "--colors", "--microfacet", "single"});
  ASSERT_EQ(own.exit_code, 0) << own.err;
  ASSERT_EQ(single.exit_code, 0) << single.err;
  const auto rows = csv_rows(own.out), single_rows = csv_rows(single.out);
  ASSERT_EQ(rows.front(), (std::vector<std::string>{"name", "microfacet", "reflectance_r", "reflectance_g",
                                                    "reflectance_b", "srgb"}));
  ASSERT_EQ(rows.size(), single_rows.size());
  ASSERT_GE(rows.size(), 15u);  // the header and every preset
  int brighter = 0;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), 6u) << own.out;
    EXPECT_EQ(rows[r][0], single_rows[r][0]);
    EXPECT_EQ(single_rows[r][1], "single");
    EXPECT_EQ(rows[r][5].size(), 7u) << rows[r][5];
    EXPECT_EQ(rows[r][5][0], '#');
    if (rows[r][0].starts_with("paper-")) {
      EXPECT_EQ(rows[r][1], "single") << "the paper's presets keep its model";
    }
    for (int c = 2; c <= 4; ++c) {
      const double kept = std::stod(rows[r][c]), lost = std::stod(single_rows[r][c]);
      EXPECT_GT(kept, 0.0) << rows[r][0];
      EXPECT_GE(kept, lost - 1e-12) << rows[r][0] << " channel " << c - 2;
      if (kept > lost * 1.01) ++brighter;
    }
  }
  EXPECT_GT(brighter, 10) << "the kept light shows in the rough presets' colours";
  // The same numbers as `albedo` at normal incidence, for an RGB preset and a spectral skin.
  for (const std::string name : {"jade", "skin-fair"}) {
    const ProcessResult albedo = run_skinlayer({"albedo", "--preset", name, "--theta-i", "0"});
    ASSERT_EQ(albedo.exit_code, 0) << albedo.err;
    const auto table = csv_rows(albedo.out);
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r[0] == name; });
    ASSERT_NE(row, rows.end()) << name;
    for (int c = 0; c < 3; ++c) {
      const std::string column = std::string("reflectance_") + "rgb"[c];
      const auto at = std::find(table[0].begin(), table[0].end(), column);
      ASSERT_NE(at, table[0].end()) << column << " in " << albedo.out;
      EXPECT_NEAR(std::stod(table[1][static_cast<std::size_t>(at - table[0].begin())]),
                  std::stod((*row)[static_cast<std::size_t>(2 + c)]), 1e-9)
          << name << " " << column;
    }
  }
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"presets", "--microfacet", "single"}), 2, {"--colors"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"presets", "--colors", "--microfacet", "some"}), 2,
                                   {"microfacet", "multiple", "single"}));
}

TEST_F(MaterialCommands, EveryFailureIsOneLineAndWritesNothing) {
  std::ofstream(path("typo.json")) << R"({"format": "skinlayer-material", "version": 1,
  "top": {"sigma": 0.5, "eta": 1.4}, "layers": [{"T": 0.2, "albedo": 1, "g": 0.8}],
  "bottom": {"type": "air", "sigmaa": 0.3}})";
  std::ofstream(path("broken.json")) << "{\"format\": \"skinlayer-material\",\n \"version\": 1,,\n}";
  EXPECT_TRUE(failed_with_one_line(eval_with({"--material", path("typo.json")}), 2,
                                   {"typo.json", "unknown key \"bottom.sigmaa\"", "sigma, eta"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--material", path("broken.json")}), 2, {"broken.json:2:", "JSON"}));
  EXPECT_TRUE(
      failed_with_one_line(eval_with({"--material", path("missing.json")}), 2, {"missing.json", "cannot read"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--preset", "nope"}), 2, {"unknown preset \"nope\"", "skin-fair"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--preset", "wax", "--material", path("typo.json")}), 2,
                                   {"--material", "--preset"}));
  EXPECT_TRUE(
      failed_with_one_line(eval_with({"--preset", "paint-red-base", "--albedo", "0.5", "--bottom-sigma", "0.2"}), 2,
                           {"bottom-sigma", "lambert", "paint-red-base"}));
  // An unwritable output: exit status 1 like any failed write, and no file, partial or temporary, left behind.
  const ProcessResult unwritable = run_skinlayer({"material", "-o", path("no-such-folder/m.json")});
  EXPECT_TRUE(failed_with_one_line(unwritable, 1, {"no-such-folder/m.json"}));
  fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
  const ProcessResult read_only = run_skinlayer({"material", "-o", path("m.json")});
  fs::permissions(dir_, fs::perms::owner_all);
  if (::geteuid() != 0) {  // root writes anyway
    EXPECT_TRUE(failed_with_one_line(read_only, 1, {"m.json"}));
  }
  for (const std::string& name : entries()) {
    EXPECT_TRUE(name == "typo.json" || name == "broken.json" || (name == "m.json" && ::geteuid() == 0)) << name;
  }
}

// What a newcomer gives --material by mistake gets one line that says what the file is: a folder (exit 2, as a
// missing file), or one of skinlayer's own exports, which carry the fit but are not a material.
TEST_F(MaterialCommands, AFolderOrAnExportGivenAsTheMaterialSaysWhatItIs) {
  EXPECT_TRUE(failed_with_one_line(eval_with({"--material", dir_.string()}), 2, {"is a folder, not a material file"}));
  const std::vector<std::pair<std::string, std::string>> exports = {
      {"rgl", "x.bsdf"}, {"mtlx", "x.mtlx"}, {"blender", "x.py"}, {"gltf", "x.gltf"}};
  for (const auto& [format, name] : exports) {
    const ProcessResult exported =
        run_skinlayer({"export", "--format", format, "--preset", "paper-thin", "-o", path(name)});
    ASSERT_EQ(exported.exit_code, 0) << exported.err;
    const std::string made_by = "export --format " + format;
    EXPECT_TRUE(
        failed_with_one_line(eval_with({"--material", path(name)}), 2, {name, made_by, "not a material", ".json"}))
        << format;
  }
}

}  // namespace
}  // namespace skinlayer::test
