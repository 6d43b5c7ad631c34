// The biophysical skin on the command line (--skin, `spectrum`, --wavelength), on the real executable: the spectrum's
// shape and energy, eval's and albedo's RGB columns as the linear-sRGB mix of the per-wavelength values that
// `spectrum` and `eval --wavelength` write (with core's weights, which tests/core/color/spectral_color_test.cpp
// checks against the CIE's published white point and the sRGB matrix), and every error as one line naming the key
// and its range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <string>
#include <vector>

#include "core/color/spectral_color.h"
#include "tests/app/csv_output.h"
#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

CsvOutput run_csv(const std::vector<std::string>& arguments, std::string_view stdin_text = "") {
  const ProcessResult result = run_skinlayer(arguments, stdin_text);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return parse_csv_output(result.out);
}

std::size_t column(const CsvOutput& csv, const std::string& name) {
  for (std::size_t i = 0; i < csv.header.size(); ++i)
    if (csv.header[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

const std::string kSkin = "melanin=0.03,blood=0.01,oxygenation=0.9";

TEST(SkinCommands, SpectrumCoversTheVisibleAndAccountsForEveryPhoton) {
  const CsvOutput csv = run_csv({"spectrum", "--skin", kSkin, "--theta-i", "8,60"});
  EXPECT_EQ(csv.header, (std::vector<std::string>{"theta_i", "wavelength_nm", "reflectance", "transmittance",
                                                  "absorptance", "absorptance_layer1", "absorptance_layer2"}));
  ASSERT_EQ(csv.rows.size(), 2u * 31u);
  EXPECT_EQ(csv.rows.front()[1], 400.0);
  EXPECT_EQ(csv.rows[30][1], 700.0);
  EXPECT_EQ(csv.rows[31][0], 60.0);
  for (const std::vector<double>& row : csv.rows) {
    EXPECT_NEAR(row[2] + row[3] + row[4], 1.0, 1e-6);
    EXPECT_LE(row[5] + row[6], row[4] + 1e-9);  // the media's share of the absorptance
    EXPECT_GT(row[2], 0.0);
  }
}

TEST(SkinCommands, AGreyMaterialHasAFlatSpectrumEqualToItsAlbedo) {
  const CsvOutput spectrum = run_csv({"spectrum", "--albedo", "0.9", "--T", "0.5", "--theta-i", "30"});
  const CsvOutput albedo = run_csv({"albedo", "--albedo", "0.9", "--T", "0.5", "--theta-i", "30"});
  ASSERT_EQ(spectrum.rows.size(), 31u);
  for (const std::vector<double>& row : spectrum.rows) {
    EXPECT_EQ(row[2], albedo.rows[0][column(albedo, "reflectance")]);
    EXPECT_EQ(row[3], albedo.rows[0][column(albedo, "transmittance")]);
  }
  const CsvOutput one =
      run_csv({"spectrum", "--albedo", "0.9", "--T", "0.5", "--theta-i", "30", "--wavelength", "555"});
  ASSERT_EQ(one.rows.size(), 1u);
  EXPECT_EQ(one.rows[0][2], spectrum.rows[0][2]);
}

// The RGB columns are the spectrum's linear sRGB: sum_k w_c(lambda_k) value(lambda_k).
TEST(SkinCommands, AlbedoRgbIsTheSpectrumsColour) {
  const CsvOutput spectrum = run_csv({"spectrum", "--skin", kSkin, "--theta-i", "8"});
  const CsvOutput albedo = run_csv({"albedo", "--skin", kSkin, "--theta-i", "8"});
  std::vector<double> wavelengths;
  Eigen::VectorXd reflectance(static_cast<Eigen::Index>(spectrum.rows.size()));
  for (std::size_t k = 0; k < spectrum.rows.size(); ++k) {
    wavelengths.push_back(spectrum.rows[k][1]);
    reflectance(static_cast<Eigen::Index>(k)) = spectrum.rows[k][2];
  }
  const Eigen::Vector3d rgb = linear_srgb_weights(wavelengths) * reflectance;
  const char* const names[3] = {"reflectance_r", "reflectance_g", "reflectance_b"};
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(albedo.rows[0][column(albedo, names[c])], rgb(c), 1e-9) << names[c];
  // Light skin is red over green over blue, and bright enough to be skin (NIST's forearms: 0.26-0.66 at 649 nm).
  EXPECT_GT(rgb(0), rgb(1));
  EXPECT_GT(rgb(1), rgb(2));
  EXPECT_GT(rgb(0), 0.25);
}

TEST(SkinCommands, EvalRgbIsTheMixOfItsWavelengths) {
  const std::string rows = "theta_i,theta_o,phi\n8,8,180\n40,20,90\n70,60,0\n";
  const CsvOutput rgb = run_csv({"eval", "--skin", kSkin}, rows);
  ASSERT_EQ(rgb.rows.size(), 3u);
  std::vector<double> wavelengths;
  for (double w = 400; w <= 700; w += 10) wavelengths.push_back(w);
  const Eigen::Matrix<double, 3, Eigen::Dynamic> weights = linear_srgb_weights(wavelengths);
  Eigen::MatrixXd subsurface(3, static_cast<Eigen::Index>(wavelengths.size()));
  for (std::size_t k = 0; k < wavelengths.size(); ++k) {
    const CsvOutput one = run_csv({"eval", "--skin", kSkin, "--wavelength", std::to_string(wavelengths[k])}, rows);
    ASSERT_EQ(one.header[4], "brdf_subsurface");
    for (int r = 0; r < 3; ++r) subsurface(r, static_cast<Eigen::Index>(k)) = one.rows[static_cast<std::size_t>(r)][4];
    for (int r = 0; r < 3; ++r)
      EXPECT_EQ(one.rows[static_cast<std::size_t>(r)][3], rgb.rows[static_cast<std::size_t>(r)][3]);
  }
  const char* const names[3] = {"brdf_subsurface_r", "brdf_subsurface_g", "brdf_subsurface_b"};
  for (int r = 0; r < 3; ++r) {
    const Eigen::Vector3d mixed = weights * subsurface.row(r).transpose();
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(rgb.rows[static_cast<std::size_t>(r)][column(rgb, names[c])], mixed(c), 1e-9 * mixed(c));
    }
  }
}

TEST(SkinCommands, BadSkinValuesAreOneLineNamingTheKeyAndItsRange) {
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"spectrum", "--skin", "blood=0.3"}), 2,
                                   {"skin: blood = 0.3 is out of range", "[0, 0.2]"}));
  EXPECT_TRUE(
      failed_with_one_line(run_skinlayer({"albedo", "--skin", "scattering=5"}), 2, {"scattering", "[0.25, 4]"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"spectrum", "--skin", "melanine=0.1"}), 2,
                                   {"unknown key 'melanine'", "melanin, eumelanin, blood"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"spectrum", "--skin", "melanin=nan"}), 2, {"melanin", "[0, 0.5]"}));
  EXPECT_TRUE(
      failed_with_one_line(run_skinlayer({"spectrum", "--skin", "melanin=0.1,melanin=0.2"}), 2, {"more than once"}));
  EXPECT_TRUE(
      failed_with_one_line(run_skinlayer({"eval", "--skin", "melanin=0.1", "--T", "0.3"}), 2, {"--T", "--skin"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"spectrum", "--skin", "melanin=0.1", "--wavelength", "900"}), 2,
                                   {"wavelength = 900", "[360, 830]"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"albedo", "--preset", "paper-skin", "--wavelength", "500"}), 2,
                                   {"RGB material has none"}));
  // An RGB albedo where a spectrum is asked for: the reason, not "is not a number".
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"spectrum", "--albedo", "0.5,0.6,0.7"}), 2,
                                   {"albedo = '0.5,0.6,0.7'", "one albedo", "grey", "--skin"}));
}

// A skin material file (as `material --skin` writes it) reads back into the same spectrum; render and export take it,
// and the exported .bsdf carries the skin, which reads back into the same spectrum again.
TEST(SkinCommands, ASkinMaterialFileGivesTheSameSpectrumAndRendersAndExports) {
  const ProcessResult written = run_skinlayer({"material", "--skin", kSkin, "--sigma", "0.35"});
  ASSERT_EQ(written.exit_code, 0) << written.err;
  const std::string path = ::testing::TempDir() + "skinlayer_skin_material.json";
  std::ofstream(path) << written.out;
  const CsvOutput from_file = run_csv({"spectrum", "--material", path, "--theta-i", "8"});
  const CsvOutput from_flags = run_csv({"spectrum", "--skin", kSkin, "--sigma", "0.35", "--theta-i", "8"});
  EXPECT_EQ(from_file.rows, from_flags.rows);

  const ProcessResult rendered = run_skinlayer({"render", "--material", path, "--size", "64x64", "-o", path + ".png"});
  EXPECT_EQ(rendered.exit_code, 0) << rendered.err;
  EXPECT_GT(std::ifstream(path + ".png", std::ios::binary | std::ios::ate).tellg(), 100);
  const ProcessResult exported =
      run_skinlayer({"export", "--format", "bsdf", "--nodes", "12", "--material", path, "-o", path + ".bsdf"});
  EXPECT_EQ(exported.exit_code, 0) << exported.err;
  const CsvOutput from_bsdf = run_csv({"spectrum", "--material", path + ".bsdf", "--theta-i", "8"});
  EXPECT_EQ(from_bsdf.rows, from_flags.rows);
  for (const std::string& file : {path, path + ".png", path + ".bsdf"}) std::remove(file.c_str());
}

// The normal-incidence linear sRGB of a material as albedo writes it (surface and subsurface).
Eigen::Vector3d normal_color(const std::vector<std::string>& material_flags) {
  std::vector<std::string> arguments = {"albedo", "--theta-i", "0"};
  arguments.insert(arguments.end(), material_flags.begin(), material_flags.end());
  const CsvOutput csv = run_csv(arguments);
  const auto& header = csv.header;
  if (std::find(header.begin(), header.end(), "reflectance") != header.end()) {  // a grey material
    return Eigen::Vector3d::Constant(csv.rows[0][column(csv, "reflectance")]);
  }
  return {csv.rows[0][column(csv, "reflectance_r")], csv.rows[0][column(csv, "reflectance_g")],
          csv.rows[0][column(csv, "reflectance_b")]};
}

std::string linear_text(const Eigen::Vector3d& rgb) {
  char text[96];
  std::snprintf(text, sizeof text, "%.17g,%.17g,%.17g", rgb(0), rgb(1), rgb(2));
  return text;
}

class MatchCommand : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return ::testing::TempDir() + "skinlayer_match_" + name; }
};

TEST_F(MatchCommand, ASkinColourRoundTripsWithinHalfAPercent) {
  const std::vector<std::string> skins = {"melanin=0.01,blood=0.004,scattering=1.6", "melanin=0.2,blood=0.03",
                                          "melanin=0.08,blood=0.06,scattering=0.6"};
  for (const std::string& skin : skins) {
    const Eigen::Vector3d target = normal_color({"--skin", skin});
    const std::string out = path("round_trip.json");
    const ProcessResult result =
        run_skinlayer({"match", "--color", linear_text(target), "--linear", "--skin", "eumelanin=0.7", "-o", out});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.err, "") << "a reachable colour says nothing";
    const Eigen::Vector3d reached = normal_color({"--material", out});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(reached(c), target(c), 0.005 * target(c)) << skin << " channel " << c;
    std::remove(out.c_str());
  }
}

// A colour alone is matched as a skin's, and the command says so first: skin-fair's own colour is reached, where the
// paper's grey layer stayed 17.7 CIEDE2000 away from it.
TEST_F(MatchCommand, AColourAloneIsASkinsAndTheCommandSaysSo) {
  const ProcessResult result = run_skinlayer({"match", "--color", "#C09F8B"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("\"skin\""), std::string::npos) << result.out;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find("matching a skin"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("--preset"), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find("out of reach"), std::string::npos) << result.err;
}

TEST_F(MatchCommand, ALayeredMaterialGetsItsTopAlbedoPerChannel) {
  const Eigen::Vector3d target(0.5, 0.3, 0.2);
  const std::string out = path("wax.json");
  const ProcessResult result =
      run_skinlayer({"match", "--color", "0.5,0.3,0.2", "--linear", "--preset", "wax", "-o", out});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const Eigen::Vector3d reached = normal_color({"--material", out});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(reached(c), target(c), 0.005 * target(c)) << "channel " << c;
  // sRGB-encoded by default: #808080 is linear 0.2159.
  const ProcessResult grey = run_skinlayer({"match", "--color", "#808080", "--preset", "wax", "-o", out});
  ASSERT_EQ(grey.exit_code, 0) << grey.err;
  const Eigen::Vector3d reached_grey = normal_color({"--material", out});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(reached_grey(c), 0.21586, 0.005 * 0.21586);
  std::remove(out.c_str());
}

TEST_F(MatchCommand, AnUnreachableColourGivesTheNearestAndOneLineWithTheDistance) {
  const ProcessResult result = run_skinlayer({"match", "--color", "0.1,0.2,0.9", "--skin", "melanin=0.02"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("\"skin\""), std::string::npos);
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1);
  EXPECT_NE(result.err.find("out of reach"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("CIEDE2000"), std::string::npos) << result.err;
  // White is beyond any material whose interfaces lose light (Stam's single-scattering ones): the nearest is
  // Omega = 1. With the interfaces that keep it (the default) a white layer is white.
  const ProcessResult lossy = run_skinlayer({"match", "--color", "1,1,1", "--preset", "wax", "--microfacet", "single"});
  EXPECT_NE(lossy.err.find("out of reach"), std::string::npos) << lossy.err;
  const ProcessResult white = run_skinlayer({"match", "--color", "1,1,1", "--preset", "wax"});
  EXPECT_EQ(white.exit_code, 0) << white.err;
  EXPECT_EQ(white.err.find("out of reach"), std::string::npos) << white.err;
}

TEST_F(MatchCommand, ASpectrumOfTheModelIsFitClosely) {
  const CsvOutput spectrum = run_csv({"spectrum", "--skin", "melanin=0.1,blood=0.02,epidermis=0.08", "--theta-i", "8"});
  const std::string csv = path("spectrum.csv");
  {
    std::ofstream file(csv);
    file << "wavelength_nm,reflectance\n";
    for (const std::vector<double>& row : spectrum.rows)
      file << row[1] << "," << std::setprecision(17) << row[2] << "\n";
  }
  const ProcessResult fit = run_skinlayer({"match", "--spectrum", csv});
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  EXPECT_NE(fit.out.find("\"skin\""), std::string::npos);
  const std::size_t at = fit.err.find("RMS residual ");
  ASSERT_NE(at, std::string::npos) << fit.err;
  EXPECT_LT(std::stod(fit.err.substr(at + 13)), 2e-3) << fit.err;
  std::remove(csv.c_str());
}

// The files people have: one that descends (many spectrometers write red first), with blank lines, reads as the
// same spectrum; one in per cent gets one line that says so; both --color and --spectrum say "not both".
TEST_F(MatchCommand, ADescendingSpectrumReadsAsItsAscendingOneAndPerCentGetsAHint) {
  const CsvOutput spectrum = run_csv({"spectrum", "--skin", "melanin=0.1,blood=0.02,epidermis=0.08", "--theta-i", "8"});
  const std::string up = path("up.csv"), down = path("down.csv"), percent = path("percent.csv");
  {
    std::ofstream ascending(up), descending(down), in_percent(percent);
    ascending << "wavelength_nm,reflectance\n";
    descending << "wavelength_nm,reflectance\n\n";
    in_percent << "wavelength_nm,reflectance\n";
    for (const std::vector<double>& row : spectrum.rows) {
      ascending << row[1] << "," << std::setprecision(17) << row[2] << "\n";
      in_percent << row[1] << "," << std::setprecision(17) << 100.0 * row[2] << "\n";
    }
    for (auto row = spectrum.rows.rbegin(); row != spectrum.rows.rend(); ++row) {
      descending << (*row)[1] << "," << std::setprecision(17) << (*row)[2] << "\n\n";
    }
  }
  const ProcessResult from_up = run_skinlayer({"match", "--spectrum", up});
  const ProcessResult from_down = run_skinlayer({"match", "--spectrum", down});
  ASSERT_EQ(from_up.exit_code, 0) << from_up.err;
  ASSERT_EQ(from_down.exit_code, 0) << from_down.err;
  EXPECT_EQ(from_down.out, from_up.out);
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"match", "--spectrum", percent}), 1,
                                   {"percent.csv:2:", "above 1.5", "per cent", "divide it by 100"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"match", "--color", "#C09F8B", "--spectrum", up}), 2,
                                   {"--color", "--spectrum", "not both"}));
  for (const std::string& file : {up, down, percent}) std::remove(file.c_str());
}

TEST_F(MatchCommand, BadRequestsAreOneLine) {
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"match", "--color", "#12345"}), 2, {"#RRGGBB"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"match", "--color", "1.2,0,0"}), 2, {"1.2", "[0, 1]"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"match", "--color", "0.5,0.5"}), 2, {"R,G,B"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"match"}), 2, {"--color", "--spectrum"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"match", "--spectrum", "/nonexistent.csv"}), 2, {"cannot be read"}));
  EXPECT_TRUE(
      failed_with_one_line(run_skinlayer({"match", "--color", "0.5,0.5,0.5", "--theta-i", "8"}), 2, {"--spectrum"}));
}

}  // namespace
}  // namespace skinlayer::test
