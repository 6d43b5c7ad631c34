// skinlayer validate --quick, run as CI's solver-against-Monte-Carlo check under both interface models: every set of
// the grid must agree within 4 Monte Carlo standard errors (the exit status), and the report and one plot per set
// must be written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/validate/validation_grid.h"
#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The quick grid (or the named sets of it) under one interface model: every set agrees (the exit status), and the
// report and one plot per set are written, each remembering its set's material.
void expect_quick_run_agrees(const std::string& folder, const std::vector<std::string>& model_flags,
                             const std::vector<std::string>& sets = {}) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / folder;
  std::filesystem::remove_all(dir);
  // Two threads whatever the machine: a Monte Carlo result is reproducible for a given seed and thread count.
  std::vector<std::string> arguments = {"validate", "--quick", "--threads", "2", "-o", dir.string()};
  arguments.insert(arguments.end(), model_flags.begin(), model_flags.end());
  std::string names;
  for (const std::string& set : sets) names += (names.empty() ? "" : ",") + set;
  if (!names.empty()) arguments.insert(arguments.end(), {"--set", names});
  const ProcessResult run = run_skinlayer(arguments);
  std::printf("%s", run.out.c_str());
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("[1/"), std::string::npos);
  EXPECT_NE(run.out.find("sets agree within 4 standard errors"), std::string::npos);

  const std::string report = read_file(dir / "validation.md");
  for (const validation::ValidationSet& set : validation::validation_grid()) {
    if (!sets.empty() && std::find(sets.begin(), sets.end(), set.name) == sets.end()) continue;
    const std::string png = read_file(dir / (set.name + ".png"));
    ASSERT_GT(png.size(), 8u) << set.name;
    EXPECT_EQ(png.substr(1, 3), "PNG") << set.name;
    EXPECT_NE(report.find("## " + set.name + "\n"), std::string::npos) << set.name;
    EXPECT_NE(report.find("](" + set.name + ".png)"), std::string::npos) << set.name;
    const ProcessResult material = run_skinlayer({"material", "--material", (dir / (set.name + ".png")).string()});
    EXPECT_NE(material.out.find("\"name\": \"" + set.name + "\""), std::string::npos) << material.err;
  }
  EXPECT_EQ(report.find("**disagrees**"), std::string::npos);
}

// The default interfaces keep the light that meets the microsurface more than once, and the photons walk on it:
// everything the solver computes is judged, the bins in the plane of incidence included.
TEST(ValidateCommand, QuickRunUnderTheDefaultInterfacesAgreesEverywhere) {
  expect_quick_run_agrees("skinlayer-validate-quick", {});
}

// Stam's single-scattering interfaces, whose lost light both sides leave out: the sets whose light their interfaces
// shape (every kind of bottom and interface, sharp and rough, grazing light, a stack with an interface between its
// layers). The sets that vary the medium alone solve it as the default run does; CI's time (45 minutes on two
// cores) does not run them twice. `skinlayer validate --quick --microfacet single` runs them all.
TEST(ValidateCommand, QuickRunUnderStamsInterfacesAgreesEverywhere) {
  expect_quick_run_agrees("skinlayer-validate-quick-single", {"--microfacet", "single"},
                          {"paper-default", "paper-grazing", "paper-sigma-0.1", "sigma-1", "eta-2", "eta-1.2",
                           "bottom-matched", "bottom-unlike", "thin", "sharp-0.2-air", "sharp-0.05-air",
                           "sharp-0.05-matched", "stack-interface"});
}

TEST(ValidateCommand, BadFlagsAreUsageErrors) {
  EXPECT_EQ(run_skinlayer({"validate", "--microfacet", "double"}).exit_code, 2);
  EXPECT_EQ(run_skinlayer({"validate", "--quick=1"}).exit_code, 2);
  EXPECT_EQ(run_skinlayer({"validate", "--set", "no-such-set"}).exit_code, 2);
  EXPECT_EQ(run_skinlayer({"validate", "--threads", "0"}).exit_code, 2);
  EXPECT_EQ(run_skinlayer({"validate", "--seed", "nan"}).exit_code, 2);
  const ProcessResult bad = run_skinlayer({"validate", "--set", "no-such-set"});
  EXPECT_NE(bad.err.find("paper-default"), std::string::npos) << "the error lists the sets: " << bad.err;
}

TEST(ValidateCommand, OneSetRunsWithItsOwnSeed) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "skinlayer-validate-one";
  const ProcessResult alone =
      run_skinlayer({"validate", "--quick", "--threads", "2", "--set", "eta-1", "-o", dir.string()});
  EXPECT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_NE(alone.out.find("[1/1] eta-1"), std::string::npos);
}

}  // namespace
}  // namespace skinlayer::test
