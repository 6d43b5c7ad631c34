// The user guide (docs/guide/commands.md and exports.md) and every command's --help agree on the flags, on the real
// executable:
//  - each flag that a command's --help lists is in that command's section of the guide (from its heading
//    "### `skinlayer COMMAND ..." to the next heading of level 1 to 3), or, for a command that takes material
//    flags, in the guide's "## Material flags" section (with its subsections);
//  - each flag that the guide gives a command, in its section's heading or in the first column of its flag tables,
//    is one that the command's --help lists.
// The previewer (`skinlayer [material flags]`, the section "### `skinlayer [material flags]`: the previewer", and
// "### `skinlayer --capture ...") is held to the usage it prints for `skinlayer --view both --help`.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/process_runner.h"

namespace skinlayer::test {
namespace {

using FlagSet = std::set<std::string>;

FlagSet flags_in(const std::string& text) {
  static const std::regex flag(R"((^|[^A-Za-z0-9_-])(--[a-z][a-z0-9-]*))");
  FlagSet flags;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), flag); it != std::sregex_iterator(); ++it) {
    flags.insert((*it)[2].str());
  }
  return flags;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot read " << path;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int heading_level(const std::string& line) {
  int level = 0;
  while (level < static_cast<int>(line.size()) && line[static_cast<std::size_t>(level)] == '#') ++level;
  return level > 0 && level < static_cast<int>(line.size()) && line[static_cast<std::size_t>(level)] == ' ' ? level
                                                                                                            : 0;
}

// The command a "### `skinlayer ..." heading documents: its first word; "previewer" for the window's sections.
std::string heading_command(const std::string& line) {
  const std::string prefix = "### `skinlayer ";
  if (!line.starts_with(prefix)) return "";
  const std::string rest = line.substr(prefix.size());
  if (rest.starts_with("[material flags]") || rest.starts_with("--capture")) return "previewer";
  if (rest.starts_with("-") || rest.starts_with("[")) return "";  // --version
  return rest.substr(0, rest.find_first_of(" `"));
}

struct Guide {
  std::map<std::string, std::string> sections;  // command -> its section's text
  std::map<std::string, FlagSet> tabled;        // command -> the flags in its heading and its tables' first column
  std::string material_flags;                   // the "## Material flags" section with its subsections
};

FlagSet first_column_flags(const std::string& line) {
  if (!line.starts_with("| ")) return {};
  const std::size_t end = line.find(" |", 1);
  return flags_in(line.substr(0, end));
}

Guide read_guide() {
  Guide guide;
  std::string command;
  bool in_material = false;
  for (const char* page : {"commands.md", "exports.md"}) {
    std::istringstream lines(read_text(std::string(SKINLAYER_GUIDE_DIR) + "/" + page));
    for (std::string line; std::getline(lines, line);) {
      const int level = heading_level(line);
      if (level >= 1 && level <= 3) {
        command = heading_command(line);
        if (level <= 2) in_material = line == "## Material flags";
        if (!command.empty()) {
          const FlagSet heading = flags_in(line);
          guide.tabled[command].insert(heading.begin(), heading.end());
        }
      }
      if (in_material) guide.material_flags += line + "\n";
      if (command.empty()) continue;
      guide.sections[command] += line + "\n";
      const FlagSet tabled = first_column_flags(line);
      guide.tabled[command].insert(tabled.begin(), tabled.end());
    }
  }
  return guide;
}

std::string help_of(const std::string& command) {
  const ProcessResult help =
      command == "previewer" ? run_skinlayer({"--view", "both", "--help"}) : run_skinlayer({command, "--help"});
  EXPECT_EQ(help.exit_code, 0) << command << ": " << help.err;
  return help.out;
}

TEST(GuideFlags, EveryFlagOfEveryHelpIsInTheGuideAndEveryFlagTheGuideGivesIsInTheHelp) {
  const Guide guide = read_guide();
  ASSERT_FALSE(guide.material_flags.empty()) << "no \"## Material flags\" section in the guide";
  const FlagSet material_flags = flags_in(guide.material_flags);
  std::vector<std::string> commands = skinlayer_command_names();
  ASSERT_GE(commands.size(), 10u);
  commands.push_back("previewer");
  for (const std::string& command : commands) {
    SCOPED_TRACE(command);
    const auto section = guide.sections.find(command);
    ASSERT_NE(section, guide.sections.end()) << "the guide has no section \"### `skinlayer " << command << " ...\"";
    const std::string help = help_of(command);
    const FlagSet in_help = flags_in(help);
    const FlagSet in_section = flags_in(section->second);
    const bool takes_material_flags = help.find("material flags") != std::string::npos;
    for (const std::string& flag : in_help) {
      const bool documented = in_section.contains(flag) || (takes_material_flags && material_flags.contains(flag));
      EXPECT_TRUE(documented) << command << " --help lists " << flag << ", which its section of the guide does not";
    }
    for (const std::string& flag : guide.tabled.at(command)) {
      EXPECT_TRUE(in_help.contains(flag)) << "the guide gives " << command << " the flag " << flag
                                          << ", which its --help does not list";
    }
  }
}

// The flag tables of the material flags name flags that a command taking material flags (eval) accepts.
TEST(GuideFlags, TheMaterialFlagsTablesNameFlagsThatEvalTakes) {
  const Guide guide = read_guide();
  const FlagSet in_help = flags_in(help_of("eval"));
  std::istringstream lines(guide.material_flags);
  int tabled = 0;
  for (std::string line; std::getline(lines, line);) {
    for (const std::string& flag : first_column_flags(line)) {
      ++tabled;
      EXPECT_TRUE(in_help.contains(flag)) << "the guide's material flags give " << flag << ", which eval does not take";
    }
  }
  EXPECT_GE(tabled, 8) << "the material flags are tabled: --sigma, --eta, --T, --tau, --albedo, --g, --bottom, ...";
}

}  // namespace
}  // namespace skinlayer::test
