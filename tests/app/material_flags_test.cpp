// The material flags: ranges from core's parameter table, strict numbers, and usage errors, on the real executable.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

// Runs albedo at one angle with the given flags; a bad flag fails before any solve.
ProcessResult albedo_with(std::vector<std::string> flags) {
  flags.insert(flags.begin(), {"albedo", "--theta-i", "30"});
  return run_skinlayer(flags);
}

struct BadFlag {
  std::vector<std::string> flags;
  std::vector<std::string_view> fragments;
};

void PrintTo(const BadFlag& bad, std::ostream* out) {
  for (const std::string& flag : bad.flags) *out << flag << ' ';
}

class CliFlagOutOfRange : public ::testing::TestWithParam<BadFlag> {};

// Core's check_parameter message: "<name> = <value> is out of range; valid range is [<min>, <max>] (...)".
TEST_P(CliFlagOutOfRange, FailsNamingTheParameterAndItsRange) {
  EXPECT_TRUE(failed_with_one_line(albedo_with(GetParam().flags), 2, GetParam().fragments));
}

INSTANTIATE_TEST_SUITE_P(
    Ranges, CliFlagOutOfRange,
    ::testing::Values(BadFlag{{"--sigma", "0.01"}, {"sigma = ", "valid range is [0.05, 1]"}},
                      BadFlag{{"--sigma", "1.5"}, {"sigma = ", "valid range is [0.05, 1]"}},
                      BadFlag{{"--eta", "0.99"}, {"eta = ", "valid range is [1, 2.5]"}},
                      BadFlag{{"--eta", "2.6"}, {"eta = ", "valid range is [1, 2.5]"}},
                      BadFlag{{"--T", "-0.1"}, {"T = ", "valid range is [0, 1]"}},
                      BadFlag{{"--T", "1.01"}, {"T = ", "valid range is [0, 1]"}},
                      BadFlag{{"--tau", "-0.5"}, {"tau = ", "valid range is [0, inf]"}},
                      BadFlag{{"--albedo", "-0.1"}, {"albedo = ", "valid range is [0, 1]"}},
                      BadFlag{{"--albedo", "1.0001"}, {"albedo = ", "valid range is [0, 1]"}},
                      BadFlag{{"--g", "0.96"}, {"g = ", "valid range is [-0.95, 0.95]"}},
                      BadFlag{{"--g", "-0.96"}, {"g = ", "valid range is [-0.95, 0.95]"}},
                      BadFlag{{"--bottom-sigma", "0.01"}, {"bottom-sigma = ", "valid range is [0.05, 1]"}},
                      BadFlag{{"--bottom-sigma", "2"}, {"bottom-sigma = ", "valid range is [0.05, 1]"}},
                      BadFlag{{"--bottom-eta", "0.5"}, {"bottom-eta = ", "valid range is [1, 2.5]"}},
                      BadFlag{{"--bottom-eta", "3"}, {"bottom-eta = ", "valid range is [1, 2.5]"}},
                      BadFlag{{"--bottom", "lambert:1.1"}, {"lambert = ", "valid range is [0, 1]"}},
                      BadFlag{{"--bottom", "lambert:-0.1"}, {"lambert = ", "valid range is [0, 1]"}},
                      BadFlag{{"--ordinates", "3"}, {"ordinates = ", "valid range is [4, 256]"}},
                      BadFlag{{"--ordinates", "257"}, {"ordinates = ", "valid range is [4, 256]"}},
                      BadFlag{{"--mu-t", "0"}, {"mu-t = ", "valid range is [1e-06, 1000000]", "1/mm"}},
                      BadFlag{{"--mu-t", "-4"}, {"mu-t = ", "valid range is [1e-06, 1000000]"}},
                      BadFlag{{"--mu-t", "2e6"}, {"mu-t = ", "valid range is [1e-06, 1000000]"}}));

class CliFlagNotANumber : public ::testing::TestWithParam<BadFlag> {};

TEST_P(CliFlagNotANumber, FailsNamingTheParameter) {
  EXPECT_TRUE(failed_with_one_line(albedo_with(GetParam().flags), 2, GetParam().fragments));
}

INSTANTIATE_TEST_SUITE_P(
    Values, CliFlagNotANumber,
    ::testing::Values(
        BadFlag{{"--sigma", "nan"}, {"sigma = "}}, BadFlag{{"--eta", "NaN"}, {"eta = "}},
        BadFlag{{"--T", "nan"}, {"T = "}}, BadFlag{{"--tau", "nan"}, {"tau = "}},
        BadFlag{{"--albedo", "nan"}, {"albedo = "}}, BadFlag{{"--g", "nan"}, {"g = "}},
        BadFlag{{"--bottom-sigma", "nan"}, {"bottom-sigma = "}}, BadFlag{{"--bottom-eta", "nan"}, {"bottom-eta = "}},
        BadFlag{{"--bottom", "lambert:nan"}, {"lambert = "}}, BadFlag{{"--ordinates", "nan"}, {"ordinates = "}},
        BadFlag{{"--sigma", "inf"}, {"sigma = "}}, BadFlag{{"--T", "-inf"}, {"T = "}},
        BadFlag{{"--tau", "-inf"}, {"tau = "}}, BadFlag{{"--g", "inf"}, {"g = "}},
        BadFlag{{"--sigma", "abc"}, {"sigma", "not a number"}}, BadFlag{{"--sigma", "0.5x"}, {"sigma", "not a number"}},
        BadFlag{{"--sigma", "+0.5"}, {"sigma", "not a number"}},
        BadFlag{{"--sigma", " 0.5"}, {"sigma", "not a number"}}, BadFlag{{"--eta="}, {"eta", "not a number"}},
        BadFlag{{"--ordinates", "8.5"}, {"ordinates", "whole number"}},
        BadFlag{{"--ordinates", "eight"}, {"ordinates", "not a number"}}, BadFlag{{"--bottom", "wood"}, {"bottom"}},
        BadFlag{{"--bottom", "lambert:"}, {"bottom"}}, BadFlag{{"--bottom", "lambert"}, {"bottom"}}));

class CliFlagUsageError : public ::testing::TestWithParam<BadFlag> {};

TEST_P(CliFlagUsageError, FailsNamingTheFlag) {
  EXPECT_TRUE(failed_with_one_line(albedo_with(GetParam().flags), 2, GetParam().fragments));
}

INSTANTIATE_TEST_SUITE_P(
    Usage, CliFlagUsageError,
    ::testing::Values(BadFlag{{"--T", "0.5", "--tau", "1"}, {"--T", "--tau"}},
                      BadFlag{{"--tau=1", "--T=0.5"}, {"--T", "--tau"}},
                      BadFlag{{"--bottom", "matched", "--bottom-sigma", "0.3"}, {"--bottom-sigma", "air"}},
                      BadFlag{{"--bottom-eta", "1.2", "--bottom", "lambert:0.5"}, {"--bottom-eta", "air"}},
                      BadFlag{{"--colour", "1"}, {"--colour"}}, BadFlag{{"--Sigma", "0.3"}, {"--Sigma"}},
                      BadFlag{{"--sigma"}, {"--sigma", "needs a value"}},
                      BadFlag{{"--sigma", "--eta", "1.2"}, {"--sigma", "needs a value"}},
                      BadFlag{{"--g", "0.1", "--g", "0.2"}, {"--g", "more than once"}},
                      BadFlag{{"--g=0.1", "--g", "0.1"}, {"--g", "more than once"}}, BadFlag{{"0.5"}, {"'0.5'"}},
                      BadFlag{{"-s", "0.5"}, {"'-s'"}}, BadFlag{{"--", "0.5"}, {"'--'"}}));

class CliFlagAccepted : public ::testing::TestWithParam<std::vector<std::string>> {};

TEST_P(CliFlagAccepted, RunsToCompletion) {
  const ProcessResult result = albedo_with(GetParam());  // automatic resolution: edges may need many ordinates
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
}

INSTANTIATE_TEST_SUITE_P(
    Edges, CliFlagAccepted,
    ::testing::Values(std::vector<std::string>{"--tau", "inf"}, std::vector<std::string>{"--tau", "INF"},
                      std::vector<std::string>{"--tau", "0"}, std::vector<std::string>{"--T", "0"},
                      std::vector<std::string>{"--T", "1"}, std::vector<std::string>{"--eta", "1"},
                      std::vector<std::string>{"--eta", "2.5"}, std::vector<std::string>{"--sigma=0.05"},
                      std::vector<std::string>{"--sigma", "1"}, std::vector<std::string>{"--g", "-0.95"},
                      std::vector<std::string>{"--g", "0.95"}, std::vector<std::string>{"--albedo", "0"},
                      std::vector<std::string>{"--bottom", "lambert:0"},
                      std::vector<std::string>{"--bottom", "lambert:1"},
                      std::vector<std::string>{"--bottom", "air", "--bottom-eta", "1", "--bottom-sigma", "1e-1"},
                      std::vector<std::string>{"--g", "-.5"}));

TEST(CliFlags, OrdinatesAcceptsWholeNumbersInRange) {
  for (const char* ordinates : {"12", "16", "64"}) {
    const ProcessResult result = run_skinlayer({"albedo", "--theta-i", "30", "--ordinates", ordinates});
    EXPECT_EQ(result.exit_code, 0) << "--ordinates " << ordinates << ": " << result.err;
  }
  const ProcessResult smooth_isotropic =
      run_skinlayer({"albedo", "--theta-i", "30", "--sigma", "1", "--g", "0", "--ordinates", "6"});
  EXPECT_EQ(smooth_isotropic.exit_code, 0) << smooth_isotropic.err;
}

// Too few ordinates for the material would create energy: an error that names the flag and the minimum.
TEST(CliFlags, OrdinatesBelowTheMaterialsMinimumAreRejected) {
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"albedo", "--ordinates", "8"}), 2,
                                   {"ordinates = 8", "valid range is [12, 256]"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"albedo", "--sigma", "0.1", "--ordinates", "32"}), 2,
                                   {"ordinates = 32", "valid range is [60, 256]"}));
}

}  // namespace
}  // namespace skinlayer::test
