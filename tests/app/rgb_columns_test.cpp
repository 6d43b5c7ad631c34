// `eval` and `albedo` with an RGB albedo (from --albedo r,g,b, a preset, a material file or a stack's
// albedo=r:g:b), on the real executable: one column per channel for each quantity that depends on colour, the
// surface term's column grey, and each channel equal to the grey solve of that channel's material, which the test
// writes as a material file of its own from the RGB material's JSON. And every preset runs through eval, albedo,
// render and export.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/app/csv_output.h"
#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"
#include "tests/app/scratch_folder.h"

namespace skinlayer::test {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kRows = "theta_i,theta_o,phi\n0,0,0\n30,25,180\n60,70,90\n80,10,0\n45,45,180\n20,60,135\n";
constexpr double kChannelTolerance = 1e-9;  // relative: each channel against the grey solve of its albedo
const char* const kChannelSuffix[3] = {"_r", "_g", "_b"};

const std::vector<std::string> kRgbEvalHeader = {"theta_i",
                                                 "theta_o",
                                                 "phi",
                                                 "brdf_surface",
                                                 "brdf_subsurface_r",
                                                 "brdf_subsurface_g",
                                                 "brdf_subsurface_b",
                                                 "brdf_r",
                                                 "brdf_g",
                                                 "brdf_b",
                                                 "btdf_r",
                                                 "btdf_g",
                                                 "btdf_b"};
const std::vector<std::string> kGreyEvalHeader = {"theta_i",         "theta_o", "phi", "brdf_surface",
                                                  "brdf_subsurface", "brdf",    "btdf"};

// A folder for one test (removed afterwards), and the test's material files.
class RgbColumns : public ScratchFolderTest {
 protected:
  // The material the flags describe, as `skinlayer material` writes it.
  nlohmann::json material_json(const std::vector<std::string>& flags) const {
    std::vector<std::string> arguments = {"material"};
    arguments.insert(arguments.end(), flags.begin(), flags.end());
    const ProcessResult result = run_skinlayer(arguments);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return nlohmann::json::parse(result.out);
  }

  // A material file of channel c alone: every layer's albedo that channel's value, everything else as it was.
  std::string channel_file(nlohmann::json material, int c) const {
    for (nlohmann::json& layer : material.at("layers")) {
      nlohmann::json& albedo = layer.at("albedo");
      if (albedo.is_array()) albedo = albedo.at(static_cast<std::size_t>(c));
    }
    const std::string file = path("channel" + std::to_string(c) + ".json");
    std::ofstream(file) << material.dump(2);
    return file;
  }
};

CsvOutput run_csv(std::vector<std::string> arguments, std::string_view stdin_text = "") {
  const ProcessResult result = run_skinlayer(arguments, stdin_text);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return parse_csv_output(result.out);
}

std::size_t column(const CsvOutput& output, const std::string& name) {
  const auto found = std::find(output.header.begin(), output.header.end(), name);
  if (found == output.header.end()) throw std::runtime_error("no column " + name);
  return static_cast<std::size_t>(found - output.header.begin());
}

::testing::AssertionResult close(double rgb, double grey) {
  if (std::abs(rgb - grey) <= kChannelTolerance * std::max(std::abs(rgb), std::abs(grey))) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << rgb << " against the grey solve's " << grey << " (relative "
                                       << std::abs(rgb - grey) / std::max(std::abs(rgb), std::abs(grey)) << ")";
}

// Column `grey_name` of the grey solve of each channel equals column grey_name + suffix of the RGB output at every
// row; with `same_in_every_channel`, the RGB output's own column grey_name (the surface term) equals it for every
// channel.
void expect_channels_match(const CsvOutput& rgb, const std::vector<CsvOutput>& greys, const std::string& grey_name,
                           bool same_in_every_channel) {
  for (int c = 0; c < 3; ++c) {
    const CsvOutput& grey = greys[static_cast<std::size_t>(c)];
    ASSERT_EQ(grey.rows.size(), rgb.rows.size());
    const std::size_t rgb_column = column(rgb, same_in_every_channel ? grey_name : grey_name + kChannelSuffix[c]);
    const std::size_t grey_column = column(grey, grey_name);
    for (std::size_t row = 0; row < rgb.rows.size(); ++row) {
      EXPECT_EQ(rgb.rows[row][0], grey.rows[row][0]);
      EXPECT_TRUE(close(rgb.rows[row][rgb_column], grey.rows[row][grey_column]))
          << rgb.header[rgb_column] << " at row " << row + 1 << ", channel " << c;
    }
  }
}

// The RGB materials: flags, a preset, a stack's albedo=r:g:b, a preset stack, two equal channels, another model.
const std::vector<std::vector<std::string>> kRgbMaterials = {
    {"--albedo", "0.9,0.6,0.3", "--sigma", "0.3", "--T", "0.4", "--g", "0.5", "--bottom", "matched"},
    {"--preset", "paper-skin"},
    {"--preset", "leaf"},  // its channels' albedos straddle the table-size rule (a shared solve differs by 0.1%)
    {"--layer", "T=0.5,albedo=0.95:0.8:0.6,g=0.7", "--layer", "T=0.3,albedo=0.7:0.9:0.99,g=0.2,sigma=0.3,eta=1.1",
     "--bottom", "lambert:0.4"},
    {"--preset", "skin-two-layer"},
    {"--albedo", "0.8,0.8,0.5", "--T", "0.1", "--bottom", "air", "--bottom-sigma", "0.2"},
    {"--albedo", "0.9,0.5,0.2", "--T", "0", "--model", "hk"},
};

TEST_F(RgbColumns, EvalWritesEachChannelAsTheGreySolveOfItsAlbedo) {
  for (const std::vector<std::string>& flags : kRgbMaterials) {
    SCOPED_TRACE(::testing::PrintToString(flags));
    std::vector<std::string> arguments = {"eval"};
    arguments.insert(arguments.end(), flags.begin(), flags.end());
    const CsvOutput rgb = run_csv(arguments, kRows);
    EXPECT_EQ(rgb.header, kRgbEvalHeader);
    const nlohmann::json material = material_json(flags);
    std::vector<CsvOutput> greys;
    for (int c = 0; c < 3; ++c) {
      greys.push_back(run_csv({"eval", "--material", channel_file(material, c)}, kRows));
      ASSERT_EQ(greys.back().header, kGreyEvalHeader);
    }
    expect_channels_match(rgb, greys, "brdf_surface", true);
    for (const char* quantity : {"brdf_subsurface", "brdf", "btdf"}) expect_channels_match(rgb, greys, quantity, false);
  }
}

TEST_F(RgbColumns, AlbedoWritesEachChannelAsTheGreySolveOfItsAlbedo) {
  for (const std::vector<std::string>& flags : kRgbMaterials) {
    if (std::find(flags.begin(), flags.end(), "--model") != flags.end()) continue;  // albedo takes no --model
    SCOPED_TRACE(::testing::PrintToString(flags));
    std::vector<std::string> arguments = {"albedo", "--theta-i", "0,45,80"};
    arguments.insert(arguments.end(), flags.begin(), flags.end());
    const CsvOutput rgb = run_csv(arguments);
    const nlohmann::json material = material_json(flags);
    const std::size_t layers = material.at("layers").size();
    std::vector<std::string> quantities = {"reflectance_subsurface", "reflectance", "transmittance", "absorptance"};
    for (std::size_t k = 1; layers > 1 && k <= layers; ++k)
      quantities.push_back("absorptance_layer" + std::to_string(k));
    std::vector<std::string> header = {"theta_i", "reflectance_surface"};
    for (const std::string& quantity : quantities) {
      for (const char* suffix : kChannelSuffix) header.push_back(quantity + suffix);
    }
    EXPECT_EQ(rgb.header, header);
    std::vector<CsvOutput> greys;
    for (int c = 0; c < 3; ++c) {
      greys.push_back(run_csv({"albedo", "--theta-i", "0,45,80", "--material", channel_file(material, c)}));
    }
    expect_channels_match(rgb, greys, "reflectance_surface", true);
    for (const std::string& quantity : quantities) expect_channels_match(rgb, greys, quantity, false);
    // Per channel, the fractions still add up to one.
    for (const std::vector<double>& row : rgb.rows) {
      for (const char* suffix : kChannelSuffix) {
        const double sum = row[column(rgb, std::string("reflectance") + suffix)] +
                           row[column(rgb, std::string("transmittance") + suffix)] +
                           row[column(rgb, std::string("absorptance") + suffix)];
        EXPECT_NEAR(sum, 1.0, 1e-12) << suffix;
      }
    }
  }
}

// --albedo A over a file's or preset's RGB albedo makes it grey again: today's columns, and the values of the
// material spelled out in grey.
TEST_F(RgbColumns, AGreyAlbedoFlagOverridesAnRgbFile) {
  const ProcessResult over_preset = run_skinlayer({"eval", "--preset", "paper-skin", "--albedo", "0.5"}, kRows);
  ASSERT_EQ(over_preset.exit_code, 0) << over_preset.err;
  EXPECT_EQ(parse_csv_output(over_preset.out).header, kGreyEvalHeader);
  nlohmann::json material = material_json({"--preset", "paper-skin"});
  material.at("layers").at(0).at("albedo") = 0.5;
  std::ofstream(path("grey.json")) << material.dump(2);
  EXPECT_EQ(over_preset.out, run_skinlayer({"eval", "--material", path("grey.json")}, kRows).out);
  const ProcessResult albedo = run_skinlayer({"albedo", "--preset", "paper-skin", "--albedo", "0.5"});
  ASSERT_EQ(albedo.exit_code, 0) << albedo.err;
  EXPECT_EQ(albedo.out, run_skinlayer({"albedo", "--material", path("grey.json")}).out);
  EXPECT_TRUE(parse_csv_output(albedo.out).header.size() == 6u) << albedo.out;
}

TEST(RgbColumnsErrors, BadRgbAlbedosAreOneLineNamingTheParameterAndItsRange) {
  EXPECT_TRUE(
      failed_with_one_line(run_skinlayer({"eval", "--albedo", "0.9,2,0.1"}, kRows), 2, {"albedo = 2", "[0, 1]"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"albedo", "--albedo", "0.9,0.1"}), 2, {"albedo", "r,g,b"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"albedo", "--albedo", "0.9,nan,0.1"}), 2, {"albedo", "nan"}));
}

// Every preset: eval and albedo write finite numbers (RGB columns where the preset is RGB or a spectral skin), render
// draws it and export writes it.
class EveryPreset : public ScratchFolderTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(EveryPreset, RunsThroughEvalAlbedoRenderAndExport) {
  const std::string& name = GetParam();
  const CsvOutput eval = run_csv({"eval", "--preset", name}, kRows);
  EXPECT_EQ(eval.rows.size(), 6u);
  const CsvOutput albedo = run_csv({"albedo", "--preset", name});
  EXPECT_EQ(albedo.rows.size(), 4u);
  for (const CsvOutput* output : {&eval, &albedo}) {
    for (const std::vector<double>& row : output->rows) {
      for (const double value : row) EXPECT_TRUE(std::isfinite(value));
    }
  }
  const ProcessResult material = run_skinlayer({"material", "--preset", name});
  ASSERT_EQ(material.exit_code, 0) << material.err;
  const nlohmann::json parsed = nlohmann::json::parse(material.out);
  bool rgb = parsed.contains("skin");  // a spectral skin writes its colour in RGB
  for (const nlohmann::json& layer : parsed.value("layers", nlohmann::json::array())) {
    rgb = rgb || layer.at("albedo").is_array();
  }
  EXPECT_EQ(eval.header == kRgbEvalHeader, rgb);
  EXPECT_EQ(eval.header == kGreyEvalHeader, !rgb);
  EXPECT_EQ(albedo.header.back().ends_with("_b"), rgb);
  const std::string png = path("preset.png");
  const ProcessResult render = run_skinlayer({"render", "--preset", name, "--size", "32x32", "-o", png});
  EXPECT_EQ(render.exit_code, 0) << render.err;
  EXPECT_TRUE(fs::is_regular_file(png));
  const std::string bsdf = path("preset.bsdf");
  const ProcessResult exported =
      run_skinlayer({"export", "--format", "bsdf", "--nodes", "8", "--preset", name, "-o", bsdf});
  EXPECT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_GT(fs::is_regular_file(bsdf) ? fs::file_size(bsdf) : 0u, 64u);
}

// The preset files of the source tree, which `skinlayer presets` must list one for one.
std::vector<std::string> preset_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(SKINLAYER_PRESET_DIR)) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Presets, EveryPreset, ::testing::ValuesIn(preset_names()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = param.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(EveryPresetListed, PresetsListsEveryPresetFile) {
  const ProcessResult listed = run_skinlayer({"presets"});
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  const std::vector<std::string> lines = split_lines(listed.out);
  const std::vector<std::string> files = preset_names();
  EXPECT_GE(files.size(), 14u);
  ASSERT_EQ(lines.size(), files.size());
  for (const std::string& name : files) {
    EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [&name](const std::string& line) {
      return line.starts_with(name + " ");
    })) << name;
  }
}

}  // namespace
}  // namespace skinlayer::test
