// Subcommand dispatch, help and version, on the real executable.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "core/material.h"
#include "tests/app/error_expectations.h"
#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

std::string formatted(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

// Every parameter of core's table appears in the command's help, with its range.
void expect_help_lists_every_parameter(const std::string& help) {
  for (const ParameterInfo& info : parameter_table()) {
    const std::string spelling = info.flag == "lambert" ? "lambert:A" : "--" + std::string(info.flag);
    EXPECT_NE(help.find(spelling), std::string::npos) << spelling;
    std::string range = "[";
    range.append(formatted(info.min)).append(", ").append(formatted(info.max)).append("]");
    EXPECT_NE(help.find(range), std::string::npos) << spelling << " range " << range;
    EXPECT_NE(help.find(std::string(info.description)), std::string::npos) << spelling;
  }
  EXPECT_NE(help.find("--bottom air|matched|lambert:A"), std::string::npos);
}

TEST(CliDispatch, EvalHelpListsEveryFlag) {
  const ProcessResult result = run_skinlayer({"eval", "--help"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.err, "");
  EXPECT_NE(result.out.find("theta_i,theta_o,phi,brdf_surface,brdf_subsurface,brdf,btdf"), std::string::npos);
  expect_help_lists_every_parameter(result.out);
}

TEST(CliDispatch, AlbedoHelpListsEveryFlag) {
  const ProcessResult result = run_skinlayer({"albedo", "--help"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("--theta-i"), std::string::npos);
  EXPECT_NE(result.out.find("theta_i,reflectance_surface,reflectance_subsurface,reflectance,transmittance,absorptance"),
            std::string::npos);
  expect_help_lists_every_parameter(result.out);
}

TEST(CliDispatch, HelpCommandMatchesCommandHelpFlag) {
  EXPECT_EQ(run_skinlayer({"help", "eval"}).out, run_skinlayer({"eval", "--help"}).out);
  EXPECT_EQ(run_skinlayer({"help", "albedo"}).out, run_skinlayer({"albedo", "-h"}).out);
}

TEST(CliDispatch, OverviewNamesTheCommands) {
  for (const char* flag : {"--help", "-h", "help"}) {
    const ProcessResult result = run_skinlayer({flag});
    ASSERT_EQ(result.exit_code, 0) << flag;
    EXPECT_NE(result.out.find("skinlayer eval"), std::string::npos) << flag;
    EXPECT_NE(result.out.find("skinlayer albedo"), std::string::npos) << flag;
  }
}

// Every command answers --help and -h with its usage on stdout and exit 0, whatever other flags stand beside it,
// the same text as `skinlayer help COMMAND`; and the overview names every command.
TEST(CliDispatch, EveryCommandAnswersHelp) {
  const std::string overview = run_skinlayer({"--help"}).out;
  const std::vector<std::string> commands = skinlayer_command_names();
  ASSERT_GE(commands.size(), 10u) << "eval, albedo, spectrum, match, render, material, presets, figures, ...";
  for (const std::string& command : commands) {
    const ProcessResult help = run_skinlayer({command, "--help"});
    EXPECT_EQ(help.exit_code, 0) << command << ": " << help.err;
    EXPECT_EQ(help.err, "") << command;
    EXPECT_TRUE(help.out.starts_with("Usage: skinlayer " + command)) << command << ": " << help.out;
    EXPECT_EQ(run_skinlayer({command, "-h"}).out, help.out) << command;
    EXPECT_EQ(run_skinlayer({command, "--sigma", "0.3", "--help"}).out, help.out) << command;
    EXPECT_EQ(run_skinlayer({"help", command}).out, help.out) << command;
    EXPECT_NE(overview.find("skinlayer " + command), std::string::npos) << command;
  }
}

// The overview's synopsis of each command is the command's own, line for line: the first lines of its --help up to
// the first blank one, "Usage: " and its indent taken off (the overview had drifted: fit listed one target, export
// three formats). And every synopsis line of the overview is some command's.
TEST(CliDispatch, TheOverviewGivesEachCommandsOwnSynopsis) {
  const std::string overview = run_skinlayer({"--help"}).out;
  for (const std::string& command : skinlayer_command_names()) {
    const std::string help = run_skinlayer({command, "--help"}).out;
    std::istringstream lines(help);
    std::string line, expected;
    while (std::getline(lines, line) && !line.empty()) {
      expected += "  " + line.substr(std::string("Usage: ").size()) + "\n";
    }
    EXPECT_NE(overview.find("\n" + expected), std::string::npos) << command << ": the overview lacks\n" << expected;
  }
  EXPECT_NE(overview.find("gltf"), std::string::npos);
  EXPECT_NE(overview.find("openpbr"), std::string::npos);
}

TEST(CliDispatch, VersionPrintsOneLine) {
  const ProcessResult result = run_skinlayer({"--version"});
  ASSERT_EQ(result.exit_code, 0);
  EXPECT_TRUE(result.out.starts_with("skinlayer ")) << result.out;
  EXPECT_EQ(result.out.find('\n'), result.out.size() - 1) << result.out;
}

TEST(CliDispatch, UnknownCommandIsAUsageError) {
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"evaluate"}), 2, {"'evaluate'"}));
  // A first argument that is a flag goes to the previewer, which checks its flags before any window opens.
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"--sigmaa", "0.3"}), 2, {"--sigmaa"}));
  EXPECT_TRUE(failed_with_one_line(run_skinlayer({"help", "rendering"}), 2, {"'rendering'"}));
}

}  // namespace
}  // namespace skinlayer::test
