// `skinlayer albedo`: the energy fractions' contract, run on the real executable.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/app/csv_output.h"
#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

const std::vector<std::string> kAlbedoHeader = {"theta_i",     "reflectance_surface", "reflectance_subsurface",
                                                "reflectance", "transmittance",       "absorptance"};
constexpr std::size_t kReflectanceSurface = 1;
constexpr std::size_t kReflectanceSubsurface = 2;
constexpr std::size_t kReflectance = 3;
constexpr std::size_t kTransmittance = 4;
constexpr std::size_t kAbsorptance = 5;

ProcessResult albedo(std::vector<std::string> flags) {
  flags.insert(flags.begin(), "albedo");
  return run_skinlayer(flags);
}

TEST(CliAlbedo, DefaultAnglesAreZeroThirtySixtyEighty) {
  const ProcessResult result = albedo({"--ordinates", "12"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput output = parse_csv_output(result.out);
  EXPECT_EQ(output.header, kAlbedoHeader);
  ASSERT_EQ(output.rows.size(), 4u);
  EXPECT_EQ(output.rows[0][0], 0.0);
  EXPECT_EQ(output.rows[1][0], 30.0);
  EXPECT_EQ(output.rows[2][0], 60.0);
  EXPECT_EQ(output.rows[3][0], 80.0);
}

TEST(CliAlbedo, RowsFollowTheGivenAnglesInOrder) {
  const ProcessResult result = albedo({"--theta-i", "80,0,45.5,90", "--ordinates", "12"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput output = parse_csv_output(result.out);
  ASSERT_EQ(output.rows.size(), 4u);
  EXPECT_EQ(output.rows[0][0], 80.0);
  EXPECT_EQ(output.rows[1][0], 0.0);
  EXPECT_EQ(output.rows[2][0], 45.5);
  EXPECT_EQ(output.rows[3][0], 90.0);
}

class CliAlbedoEnergy : public ::testing::TestWithParam<std::vector<std::string>> {};

// reflectance + transmittance + absorptance = 1, reflectance = surface + subsurface, each a fraction in [0, 1].
TEST_P(CliAlbedoEnergy, FractionsSumToOne) {
  std::vector<std::string> flags = GetParam();
  flags.insert(flags.end(), {"--theta-i", "0,30,60,80,89"});
  const ProcessResult result = albedo(flags);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const CsvOutput output = parse_csv_output(result.out);
  ASSERT_EQ(output.rows.size(), 5u);
  for (const std::vector<double>& row : output.rows) {
    const double total = row[kReflectance] + row[kTransmittance] + row[kAbsorptance];
    EXPECT_NEAR(total, 1.0, 1e-9) << "theta_i " << row[0];
    EXPECT_NEAR(row[kReflectance], row[kReflectanceSurface] + row[kReflectanceSubsurface], 1e-12)
        << "theta_i " << row[0];
    // A white semi-infinite layer returns all light to a few 1e-9 (the solve's Omega is 1 - 1e-9), either side.
    for (std::size_t column = 1; column < row.size(); ++column) {
      EXPECT_GE(row[column], -1e-8) << kAlbedoHeader[column] << " at theta_i " << row[0];
      EXPECT_LE(row[column], 1.0 + 1e-8) << kAlbedoHeader[column] << " at theta_i " << row[0];
    }
  }
}

// At the automatic resolution: the bounds on each fraction are physics, which a coarse --ordinates may not honour.
INSTANTIATE_TEST_SUITE_P(
    Materials, CliAlbedoEnergy,
    ::testing::Values(std::vector<std::string>{},  // the paper's default
                      std::vector<std::string>{"--bottom", "matched"},
                      std::vector<std::string>{"--bottom", "lambert:0.5"}, std::vector<std::string>{"--tau", "inf"},
                      std::vector<std::string>{"--T", "1"},
                      std::vector<std::string>{"--albedo", "0.5", "--eta", "1", "--bottom", "matched"},
                      std::vector<std::string>{"--bottom-sigma", "0.2", "--bottom-eta", "1.2", "--g", "-0.5"}));

class CliAlbedoBadAngles : public ::testing::TestWithParam<std::string> {};

TEST_P(CliAlbedoBadAngles, FailNamingTheFlag) {
  EXPECT_TRUE(failed_with_one_line(albedo({"--theta-i=" + GetParam(), "--ordinates", "12"}), 2, {"theta-i"}))
      << "--theta-i=" << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Lists, CliAlbedoBadAngles,
                         ::testing::Values("95", "-1", "90.01", "nan", "inf", "abc", "", "0,,30", "30,", "0;30",
                                           " 30"));

}  // namespace
}  // namespace skinlayer::test
