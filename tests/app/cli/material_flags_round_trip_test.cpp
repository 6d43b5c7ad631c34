// material_to_flags writes what material_from_flags reads back to the same material, bit for bit: the validation
// report prints these flags so that any set can be rerun by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "core/material.h"

namespace skinlayer::cli {
namespace {

Material read_back(const std::string& text) {
  std::istringstream words(text);
  std::vector<std::string> tokens;
  for (std::string word; words >> word;) tokens.push_back(word);
  const std::vector<std::string_view> arguments(tokens.begin(), tokens.end());
  return material_from_flags(ParsedFlags::parse(arguments, material_flag_names(), "test"));
}

void expect_same(const Material& a, const Material& b, const std::string& flags) {
  EXPECT_EQ(a.sigma, b.sigma) << flags;
  EXPECT_EQ(a.eta, b.eta) << flags;
  EXPECT_EQ(a.tau, b.tau) << flags;
  EXPECT_EQ(a.albedo, b.albedo) << flags;
  EXPECT_EQ(a.g, b.g) << flags;
  EXPECT_EQ(a.bottom.kind, b.bottom.kind) << flags;
  EXPECT_EQ(a.bottom.lambert_albedo, b.bottom.lambert_albedo) << flags;
  EXPECT_EQ(a.bottom.sigma, b.bottom.sigma) << flags;
  EXPECT_EQ(a.bottom.eta, b.bottom.eta) << flags;
  EXPECT_EQ(a.ordinates, b.ordinates) << flags;
  EXPECT_EQ(a.extinction, b.extinction) << flags;
  EXPECT_EQ(a.below, b.below) << flags;
}

TEST(MaterialToFlags, ReadsBackToTheSameMaterial) {
  std::vector<Material> materials(10);
  materials[1].tau = optical_depth_from_transparency(0.1);  // T = 0.1 must read back to the same tau
  materials[2].tau = INFINITY;                              // semi-infinite: T 0
  materials[3].tau = 0.0;                                   // T 1
  materials[4].sigma = 0.05;
  materials[4].g = -0.95;
  materials[4].albedo = 0.99;
  materials[5].bottom.kind = BottomKind::Lambert;
  materials[5].bottom.lambert_albedo = 0.8;
  materials[6].bottom.kind = BottomKind::Matched;
  materials[6].ordinates = 48;
  materials[7].bottom.sigma = 0.2;
  materials[7].bottom.eta = 1.2;
  materials[7].tau = 0.1;  // no T reads back to exactly this depth: --tau
  materials[8].extinction = 0.1 * 3;  // 0.30000000000000004 1/mm: the shortest text must keep every bit
  materials[9].extinction = 12.5;     // a stack whose layers carry their lengths (the last without one)
  materials[9].below = {StackedLayer{2.0, 0.8, 0.3, LayerInterface{0.3, 1.1}, 4.25},
                        StackedLayer{INFINITY, 0.95, 0.6, std::nullopt, std::nullopt}};
  for (const Material& material : materials) {
    const std::string flags = material_to_flags(material);
    expect_same(read_back(flags), material, flags);
  }
  EXPECT_NE(material_to_flags(materials[1]).find("--T 0.1 "), std::string::npos) << material_to_flags(materials[1]);
  EXPECT_NE(material_to_flags(materials[7]).find("--tau 0.1 "), std::string::npos) << material_to_flags(materials[7]);
  EXPECT_NE(material_to_flags(materials[9]).find(",mu_t=4.25,"), std::string::npos) << material_to_flags(materials[9]);
}

}  // namespace
}  // namespace skinlayer::cli
