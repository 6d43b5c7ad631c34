// `skinlayer profile` on the real executable: the core's profile written as CSV, in mean free paths without a
// length and in mm with --mu-t, per channel for an RGB albedo, and one line for every input it cannot take.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/skin/skin_optics.h"
#include "core/spatial/layer_profile.h"
#include "tests/app/csv_output.h"
#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The command's resolution (app/cli/profile_command.cpp), so that the numbers must agree to the last digits.
LayerProfileOptions command_options() {
  LayerProfileOptions options;
  options.resolution = {12, 16};
  options.frequencies = 40;
  return options;
}

// A layer under the top of --eta 1.4 and --sigma SIGMA, as the profile takes it.
ProfileLayer under_rough_top(double tau, double albedo, double g, double sigma) {
  Material m;
  m.eta = 1.4;
  m.sigma = sigma;
  ProfileLayer layer{tau, albedo, g};
  layer.top = top_interface(m);
  return layer;
}

ProcessResult profile(std::vector<std::string> flags) {
  flags.insert(flags.begin(), "profile");
  return run_skinlayer(flags);
}

TEST(ProfileCommand, AnnuliInMeanFreePathsAreTheCoresProfile) {
  const ProcessResult result = profile(
      {"--eta", "1", "--bottom", "matched", "--tau", "2", "--albedo", "0.9", "--g", "0.5", "--annuli", "0.25:8"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput csv = parse_csv_output(result.out);
  EXPECT_EQ(csv.header, (std::vector<std::string>{"r_inner_mfp", "r_outer_mfp", "reflectance", "transmittance"}));
  ASSERT_EQ(csv.rows.size(), 8u);
  std::vector<double> edges;
  for (int i = 0; i <= 8; ++i) edges.push_back(0.25 * i);
  const LayerProfile expected = layer_profile({2.0, 0.9, 0.5}, edges, command_options());
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(csv.rows[i][0], edges[i]);
    EXPECT_EQ(csv.rows[i][1], edges[i + 1]);
    EXPECT_NEAR(csv.rows[i][2], expected.reflectance[i], 1e-12 * expected.reflectance[i]);
    EXPECT_NEAR(csv.rows[i][3], expected.transmittance[i], 1e-12 * expected.transmittance[i]);
  }
}

// The edges are the decimals the user asked for: 3 x 0.05 is written 0.15, not 0.15000000000000002.
TEST(ProfileCommand, AnnulusEdgesAreWrittenAsTheDecimalsAskedFor) {
  const ProcessResult result = profile({"--eta", "1", "--bottom", "matched", "--tau", "2", "--annuli", "0.05:4"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::istringstream lines(result.out);
  std::string line;
  std::getline(lines, line);  // the header
  const std::vector<std::string> edges = {"0", "0.05", "0.1", "0.15", "0.2"};
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    ASSERT_TRUE(std::getline(lines, line));
    EXPECT_EQ(line.substr(0, line.find(',', line.find(',') + 1)), edges[i] + "," + edges[i + 1]) << line;
  }
}

// With --mu-t the radii are mm and the values per mm^2: mu_t r mean free paths, mu_t^2 times the values per mfp^2.
// An RGB albedo gives one column per channel, each the grey profile of its albedo.
TEST(ProfileCommand, RadiiInMillimetresPerChannel) {
  const ProcessResult result = profile({"--eta", "1", "--bottom", "matched", "--T", "0", "--albedo", "0.95,0.8,0.5",
                                        "--g", "0.7", "--mu-t", "20", "--radii", "0.01,0.1"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput csv = parse_csv_output(result.out);
  EXPECT_EQ(csv.header, (std::vector<std::string>{"r_mm", "reflectance_r", "reflectance_g", "reflectance_b",
                                                  "transmittance_r", "transmittance_g", "transmittance_b"}));
  ASSERT_EQ(csv.rows.size(), 2u);
  const double radii_mfp[] = {0.2, 2.0};
  const double albedos[] = {0.95, 0.8, 0.5};
  for (int c = 0; c < 3; ++c) {
    const LayerProfile expected = layer_profile_at({kInf, albedos[c], 0.7}, radii_mfp, command_options());
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_NEAR(csv.rows[i][1 + c], 400.0 * expected.reflectance[i], 1e-9 * 400.0 * expected.reflectance[i]);
      EXPECT_EQ(csv.rows[i][4 + c], 0.0);  // a half-space transmits nothing
    }
  }
  EXPECT_GT(csv.rows[0][1], csv.rows[1][1]);  // the profile falls away from the beam
  EXPECT_GT(csv.rows[0][1], csv.rows[0][3]);  // and with the albedo
}

// A half-space under a rough top: the core's profile with the material's own top interface.
TEST(ProfileCommand, RoughTopHalfSpaceIsTheCoresProfile) {
  const ProcessResult result =
      profile({"--eta", "1.4", "--sigma", "0.4", "--T", "0", "--albedo", "0.95", "--g", "0.8", "--radii", "0.5,2"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput csv = parse_csv_output(result.out);
  ASSERT_EQ(csv.rows.size(), 2u);
  const ProfileLayer layer = under_rough_top(kInf, 0.95, 0.8, 0.4);
  const double radii[] = {0.5, 2.0};
  const LayerProfile expected = layer_profile_at(layer, radii, command_options());
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(csv.rows[i][1], expected.reflectance[i], 1e-12 * expected.reflectance[i]);
    EXPECT_EQ(csv.rows[i][2], 0.0);
  }
}

// A skin at one wavelength is a two-layer stack under its rough top, in mm: the core's profile of that stack, with
// the dermis's extinction relative to the epidermis's.
TEST(ProfileCommand, ASkinAtOneWavelengthIsItsStacksProfileInMillimetres) {
  const ProcessResult result = profile({"--skin", "melanin=0.05", "--wavelength", "650", "--radii", "0.2,1"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput csv = parse_csv_output(result.out);
  EXPECT_EQ(csv.header, (std::vector<std::string>{"r_mm", "reflectance", "transmittance"}));
  ASSERT_EQ(csv.rows.size(), 2u);
  SkinParameters skin;
  skin.melanin = 0.05;
  const Material m = skin_material(skin, 650.0);
  ASSERT_EQ(m.below.size(), 1u);
  ProfileLayer layer{m.tau, m.albedo, m.g};
  layer.top = top_interface(m);
  layer.below = {LateralSlab{kInf, m.below[0].albedo, m.below[0].g, *m.below[0].extinction / *m.extinction}};
  const double mu_t = *m.extinction;
  const double radii[] = {0.2 * mu_t, 1.0 * mu_t};
  const LayerProfile expected = layer_profile_at(layer, radii, command_options());
  for (std::size_t i = 0; i < 2; ++i) {
    const double per_mm2 = mu_t * mu_t * expected.reflectance[i];
    EXPECT_NEAR(csv.rows[i][1], per_mm2, 1e-12 * per_mm2);
    EXPECT_EQ(csv.rows[i][2], 0.0);
  }
  EXPECT_GT(csv.rows[0][1], 10.0 * csv.rows[1][1]);  // red light still falls tenfold from 0.2 to 1 mm
}

// Diffuse light on an open half-space: the core's profile with light entering as node radiance.
TEST(ProfileCommand, DiffuseIncidenceIsTheCoresProfile) {
  const ProcessResult result = profile({"--eta", "1", "--bottom", "matched", "--T", "0", "--albedo", "0.95", "--g",
                                        "0.7", "--incidence", "diffuse", "--radii", "0.3,3"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput csv = parse_csv_output(result.out);
  ASSERT_EQ(csv.rows.size(), 2u);
  ProfileLayer layer{kInf, 0.95, 0.7};
  layer.incidence = Incidence::Diffuse;
  const double radii[] = {0.3, 3.0};
  const LayerProfile expected = layer_profile_at(layer, radii, command_options());
  for (std::size_t i = 0; i < 2; ++i)
    EXPECT_NEAR(csv.rows[i][1], expected.reflectance[i], 1e-12 * expected.reflectance[i]);
}

// An RGB albedo with two equal channels is solved once per distinct channel, and still writes three columns.
TEST(ProfileCommand, EqualChannelsAreSolvedOnceAndWrittenEach) {
  const ProcessResult result =
      profile({"--eta", "1", "--bottom", "matched", "--tau", "1", "--albedo", "0.9,0.9,0.5", "--annuli", "0.5:2"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput csv = parse_csv_output(result.out);
  ASSERT_EQ(csv.header.size(), 8u);
  // Each solve says so on the error stream.
  EXPECT_EQ(result.err, "profile: 1 of 2 distinct channels\nprofile: 2 of 2 distinct channels\n");
  for (const std::vector<double>& row : csv.rows) {
    EXPECT_EQ(row[2], row[3]);  // reflectance_r == reflectance_g
    EXPECT_EQ(row[5], row[6]);  // transmittance_r == transmittance_g
    EXPECT_GT(row[2], row[4]);  // the blue channel absorbs more
  }
}

// The command's profile at the radii 0.1 and 1 of a finite layer whose light enters spread over directions, which it
// computes on 24 nodes (app/solution/document_profile.cpp): both faces the core's. Returns the CSV's rows.
std::vector<std::vector<double>> expect_finer_profile_is_the_cores(std::vector<std::string> flags,
                                                                   const ProfileLayer& layer) {
  flags.insert(flags.end(), {"--radii", "0.1,1"});
  const ProcessResult result = profile(flags);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput csv = parse_csv_output(result.out);
  EXPECT_EQ(csv.rows.size(), 2u);
  if (csv.rows.size() != 2) return csv.rows;
  LayerProfileOptions options = command_options();
  options.resolution.ordinates = 24;
  const double radii[] = {0.1, 1.0};
  const LayerProfile expected = layer_profile_at(layer, radii, options);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(csv.rows[i][1], expected.reflectance[i], 1e-12 * expected.reflectance[i]);
    EXPECT_NEAR(csv.rows[i][2], expected.transmittance[i], 1e-12 * expected.transmittance[i]);
  }
  return csv.rows;
}

// A finite layer under a rough top transmits.
TEST(ProfileCommand, FiniteLayerUnderARoughTopTransmitsOnFinerOrdinates) {
  const std::vector<std::vector<double>> rows = expect_finer_profile_is_the_cores(
      {"--eta", "1.4", "--sigma", "0.3", "--bottom", "matched", "--tau", "1", "--albedo", "0.9", "--g", "0.8"},
      under_rough_top(1.0, 0.9, 0.8, 0.3));
  for (const std::vector<double>& row : rows) {
    EXPECT_GT(row[2], row[1]);  // a thin, forward-scattering slab sends most light through
  }
}

// The paper's layer, bounded by two rough interfaces: the core's profile with the bottom's operators.
TEST(ProfileCommand, RoughBottomIsTheCoresProfile) {
  Material m;
  m.albedo = 0.9;
  m.tau = -std::log(0.5);
  const ProfileLayer layer = profile_layer(m);
  ASSERT_TRUE(layer.rough_bottom.has_value());
  expect_finer_profile_is_the_cores({"--albedo", "0.9", "--T", "0.5"}, layer);
}

// The paper's default layer scatters conservatively (albedo 1): the core's profile, solved as the BSDF is.
TEST(ProfileCommand, ThePapersConservativeLayerIsTheCoresProfile) {
  expect_finer_profile_is_the_cores({}, profile_layer(Material{}));
}

// A rough interface between two layers, under a rough top: the core's profile with the interface's operators.
TEST(ProfileCommand, InterfaceBetweenLayersIsTheCoresProfile) {
  const ProcessResult result = profile({"--sigma", "0.35", "--layer", "tau=1,albedo=0.9,g=0.8,mu_t=20", "--layer",
                                        "tau=inf,albedo=0.99,g=0.8,mu_t=40,sigma=0.3,eta=1.1", "--radii", "0.05,0.2"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput csv = parse_csv_output(result.out);
  ASSERT_EQ(csv.rows.size(), 2u);
  ProfileLayer layer = under_rough_top(1.0, 0.9, 0.8, 0.35);
  layer.below = {LateralSlab{kInf, 0.99, 0.8, 2.0}};
  layer.faces = {RoughDielectric{1.1, 0.3, Material{}.microfacet}};
  const double radii[] = {0.05 * 20.0, 0.2 * 20.0};  // mm in the first layer's mean free paths
  const LayerProfile expected = layer_profile_at(layer, radii, command_options());
  for (std::size_t i = 0; i < 2; ++i) {
    const double per_mm2 = expected.reflectance[i] * 400.0;
    EXPECT_NEAR(csv.rows[i][1], per_mm2, 1e-12 * per_mm2);
  }
}

TEST(ProfileCommand, WhatItCannotTakeIsOneLine) {
  const std::vector<std::string> open = {"--eta", "1", "--bottom", "matched", "--albedo", "0.9"};
  const auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> flags = open;
    flags.insert(flags.end(), more.begin(), more.end());
    return profile(flags);
  };
  EXPECT_TRUE(failed_with_one_line(profile({"--eta", "1", "--bottom-eta", "1.4", "--albedo", "0.9", "--T", "0.5"}), 2,
                                   {"rough bottom interface", "bottom-eta 1.4", "--eta 1"}));
  EXPECT_TRUE(failed_with_one_line(profile({"--eta", "1", "--bottom", "lambert:0.5", "--albedo", "0.9"}), 2,
                                   {"Lambertian base", "--eta 1"}));
  EXPECT_TRUE(
      failed_with_one_line(profile({"--layer", "tau=0.5,albedo=0.9,g=0.5", "--layer", "tau=inf,albedo=0.9,g=0.5"}), 2,
                           {"extinction", "mu_t="}));
  // A preset without lengths: the missing number, not a paragraph about the geometries the profile takes.
  const ProcessResult preset = profile({"--preset", "clear-coat-red"});
  EXPECT_TRUE(failed_with_one_line(preset, 2, {"profile: the stack's layers", "mu_t="}));
  EXPECT_EQ(preset.err.find("computed so far"), std::string::npos) << preset.err;
  EXPECT_TRUE(failed_with_one_line(profile({"--eta", "1", "--layer", "tau=1,albedo=0.9,g=0.8,mu_t=20", "--layer",
                                            "tau=inf,albedo=0.99,g=0.8,mu_t=40,sigma=0.3,eta=1.1"}),
                                   2, {"interface between its layers", "--eta 1"}));
  EXPECT_TRUE(
      failed_with_one_line(profile({"--layer", "tau=1,albedo=0.9,g=0.8,mu_t=20", "--layer",
                                    "tau=2,albedo=0.99,g=0.8,mu_t=40,sigma=0.3,eta=1.1", "--bottom", "matched"}),
                           2, {"interface between its layers", "finite stack", "tau=inf"}));
  EXPECT_TRUE(failed_with_one_line(with({"--radii", "0,1"}), 2, {"radii", "'0'", "> 0"}));
  EXPECT_TRUE(failed_with_one_line(with({"--radii", "-1"}), 2, {"radii", "> 0"}));
  EXPECT_TRUE(failed_with_one_line(with({"--annuli", "0.1"}), 2, {"annuli", "DR:N"}));
  EXPECT_TRUE(failed_with_one_line(with({"--annuli", "0.1:2.5"}), 2, {"annuli", "whole number"}));
  EXPECT_TRUE(failed_with_one_line(with({"--annuli", "-0.1:5"}), 2, {"width", "> 0"}));
  EXPECT_TRUE(failed_with_one_line(with({"--annuli", "0.1:5", "--radii", "1"}), 2, {"--annuli", "--radii"}));
  EXPECT_TRUE(failed_with_one_line(with({"--incidence", "oblique"}), 2, {"oblique", "normal, diffuse"}));
  EXPECT_TRUE(failed_with_one_line(with({"--mu-t", "-3"}), 2, {"mu-t = -3", "1/mm"}));
}

}  // namespace
}  // namespace skinlayer::test
