// Stacked layers on the real executable (issue 12's command-line contract): --layer, repeated, top to bottom; one
// layer is exactly today's single layer; albedo adds one absorptance column per layer; a stack written to a file
// reads back bit for bit; every bad layer is one line naming its place, the key and the range, exit status 2.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kRows = "theta_i,theta_o,phi\n0,0,0\n30,25,180\n60,70,90\n80,10,0\n45,45,180\n";

ProcessResult eval_with(std::vector<std::string> flags) {
  flags.insert(flags.begin(), "eval");
  return run_skinlayer(flags, kRows);
}

std::vector<std::vector<double>> csv_numbers(const std::string& text, std::string* header) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, *header);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST(StackCommands, OneLayerIsExactlyTheSingleLayer) {
  const std::vector<std::vector<std::string>> pairs[] = {
      {{"--T", "0.2", "--albedo", "1", "--g", "0.8"}, {"--layer", "T=0.2,albedo=1,g=0.8"}},
      {{"--tau", "0.7", "--albedo", "0.6", "--g", "-0.3", "--bottom", "lambert:0.4"},
       {"--layer", "tau=0.7,albedo=0.6,g=-0.3", "--bottom", "lambert:0.4"}},
      {{"--eta", "1", "--T", "0", "--albedo", "0.9", "--g", "0.5"}, {"--eta", "1", "--layer", "T=0,albedo=0.9,g=0.5"}},
  };
  for (const auto& pair : pairs) {
    const ProcessResult single = eval_with(pair[0]);
    const ProcessResult stacked = eval_with(pair[1]);
    ASSERT_EQ(single.exit_code, 0) << single.err;
    ASSERT_EQ(stacked.exit_code, 0) << stacked.err;
    EXPECT_EQ(stacked.out, single.out) << ::testing::PrintToString(pair[1]);
    std::vector<std::string> albedo_single = {"albedo"}, albedo_stacked = {"albedo"};
    albedo_single.insert(albedo_single.end(), pair[0].begin(), pair[0].end());
    albedo_stacked.insert(albedo_stacked.end(), pair[1].begin(), pair[1].end());
    EXPECT_EQ(run_skinlayer(albedo_stacked).out, run_skinlayer(albedo_single).out) << "no layer columns for one";
  }
}

TEST(StackCommands, AlbedoAddsEachLayersAbsorptanceAfterTheColumnsItHad) {
  const ProcessResult result = run_skinlayer({"albedo", "--sigma", "0.35", "--layer", "tau=0.3,albedo=0.9,g=0.8",
                                              "--layer", "T=0.3,albedo=0.7,g=0.2,sigma=0.4,eta=1.15", "--layer",
                                              "T=0,albedo=0.99,g=0.7", "--theta-i", "0,45,80"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::string header;
  const std::vector<std::vector<double>> rows = csv_numbers(result.out, &header);
  EXPECT_EQ(header,
            "theta_i,reflectance_surface,reflectance_subsurface,reflectance,transmittance,absorptance,"
            "absorptance_layer1,absorptance_layer2,absorptance_layer3");
  ASSERT_EQ(rows.size(), 3u);
  for (const std::vector<double>& row : rows) {
    ASSERT_EQ(row.size(), 9u);
    EXPECT_NEAR(row[3] + row[4] + row[5], 1.0, 1e-12);
    EXPECT_EQ(row[4], 0.0) << "a semi-infinite last layer transmits nothing";
    double layers = 0.0;
    for (std::size_t i = 6; i < 9; ++i) {
      EXPECT_GT(row[i], 0.0);
      layers += row[i];
    }
    // The interfaces keep all light (--microfacet multiple, the default): the layers absorb all that is absorbed.
    EXPECT_NEAR(layers, row[5], 1e-6);
  }
}

TEST(StackCommands, AStackWrittenToAFileEvaluatesBitForBitLikeItsFlags) {
  const fs::path file = fs::temp_directory_path() / ("skinlayer_stack_" + std::to_string(::getpid()) + ".json");
  const std::vector<std::string> flags = {"--sigma",  "0.3",
                                          "--layer",  "T=0.6,albedo=0.95,g=0.8,mu_t=15",
                                          "--layer",  "tau=2,albedo=0.8,g=0.1,sigma=0.5,eta=0.9",
                                          "--bottom", "matched"};
  std::vector<std::string> write = {"material", "-o", file.string()};
  write.insert(write.end(), flags.begin(), flags.end());
  ASSERT_EQ(run_skinlayer(write).exit_code, 0);
  const ProcessResult direct = eval_with(flags);
  const ProcessResult from_file = eval_with({"--material", file.string()});
  fs::remove(file);
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  EXPECT_EQ(from_file.out, direct.out);
}

TEST(StackCommands, BadLayersAreOneLineNamingThePlaceTheKeyAndTheRange) {
  const std::string good = "T=0.5,albedo=0.9,g=0.8";
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", good, "--layer", "T=0.5,g=1.5"}), 2,
                                   {"layer 2", "g = 1.5", "[-0.95, 0.95]"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", "T=0,albedo=0.9", "--layer", good}), 2,
                                   {"layer 1", "only for the last layer"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", good, "--layer", "T=0.5,sigma=0.3"}), 2,
                                   {"layer 2", "sigma", "eta"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", good, "--layer", "T=0.5,sigma=0.3,eta=3"}), 2,
                                   {"layer 2", "eta = 3", "[0.4, 2.5]"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", good, "--layer", "albedo=0.5"}), 2, {"layer 2", "T", "tau"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", "T=0.5,colour=red"}), 2, {"layer 1", "colour", "mu_t"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", good, "--layer", "T=0.5,mu_t=-1"}), 2,
                                   {"layer 2", "mu_t = -1", "[1e-06, 1000000]", "1/mm"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", "T=0.5,mu_t=ten"}), 2, {"layer 1", "mu_t", "ten"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", "T=0.5,albedo=x"}), 2, {"layer 1", "albedo", "x"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", "T=0.5,albedo=0.9:0.8"}), 2, {"layer 1", "r:g:b"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", "T=0.5,albedo=0.9:0.8:1.7"}), 2,
                                   {"layer 1", "albedo = 1.7", "[0, 1]"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", "T=0.5,sigma=0.3,eta=1.2"}), 2, {"layer 1", "top"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--g", "0.5", "--layer", good}), 2, {"--g", "--layer"}));
  EXPECT_TRUE(failed_with_one_line(eval_with({"--layer", good, "--layer", good, "--model", "hk"}), 2,
                                   {"model = hk", "one layer"}));
}

// --T, --tau, --albedo and --g set a single layer: on a stack from a preset or a file they would change its top layer
// alone (--albedo 0.5 would leave the layers below RGB), so they are refused with the stack's own --layer flags, which
// give the same material back.
TEST(StackCommands, SingleLayerFlagsOnAStackAreRefusedWithItsLayerFlags) {
  for (const std::string flag : {"--albedo", "--T", "--tau", "--g", "--mu-t"}) {
    EXPECT_TRUE(failed_with_one_line(eval_with({"--preset", "skin-two-layer", flag, "0.5"}), 2,
                                     {flag, "skin-two-layer", "stack of 2 layers", "--layer"}));
  }
  const ProcessResult refused = eval_with({"--preset", "skin-two-layer", "--albedo", "0.5"});
  const std::string marker = "these being its own:";
  const std::size_t at = refused.err.find(marker);
  ASSERT_NE(at, std::string::npos) << refused.err;
  std::vector<std::string> flags = {"--preset", "skin-two-layer"};  // the layers replace the preset's
  std::istringstream words(refused.err.substr(at + marker.size()));
  for (std::string word; words >> word;) flags.push_back(word);
  ASSERT_EQ(flags.size(), 6u) << refused.err;
  const ProcessResult from_flags = eval_with(flags);
  const ProcessResult from_preset = eval_with({"--preset", "skin-two-layer"});
  ASSERT_EQ(from_preset.exit_code, 0) << from_preset.err;
  ASSERT_EQ(from_flags.exit_code, 0) << from_flags.err;
  std::string header_flags, header_preset;
  const auto a = csv_numbers(from_flags.out, &header_flags), b = csv_numbers(from_preset.out, &header_preset);
  EXPECT_EQ(header_flags, header_preset);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t r = 0; r < a.size(); ++r) {
    ASSERT_EQ(a[r].size(), b[r].size());
    for (std::size_t c = 0; c < a[r].size(); ++c) EXPECT_NEAR(a[r][c], b[r][c], 1e-12 * std::abs(b[r][c])) << r;
  }
  // A single-layer preset still takes them.
  EXPECT_EQ(eval_with({"--preset", "wax", "--albedo", "0.5"}).exit_code, 0);
}

TEST(StackCommands, RenderTakesAnRgbAlbedoPerLayer) {
  const fs::path png = fs::temp_directory_path() / ("skinlayer_stack_" + std::to_string(::getpid()) + ".png");
  const ProcessResult rendered =
      run_skinlayer({"render", "--size", "48x48", "--view", "sphere", "--layer", "T=0.6,albedo=0.98:0.94:0.86,g=0.8",
                     "--layer", "T=0,albedo=0.995:0.9:0.84,g=0.8", "-o", png.string()});
  EXPECT_EQ(rendered.exit_code, 0) << rendered.err;
  // The picture remembers the stack: evaluating it gives the material back (one channel: a grey --albedo is
  // refused, so read it through `material`).
  const ProcessResult material = run_skinlayer({"material", "--material", png.string()});
  fs::remove(png);
  ASSERT_EQ(material.exit_code, 0) << material.err;
  EXPECT_NE(material.out.find("0.995"), std::string::npos) << material.out;
  EXPECT_NE(material.out.find("\"T\": 0.0"), std::string::npos) << material.out;
}

}  // namespace
}  // namespace skinlayer::test
