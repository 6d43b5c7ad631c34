#include "app/cli/flag_parser.h"

#include <algorithm>

#include "app/cli/errors.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {
namespace {

constexpr std::string_view kFlagPrefix = "--";
constexpr std::string_view kOutputShortFlag = "-o";  // the one short form: -o FILE for --output FILE

bool is_known(std::span<const std::string_view> known_flags, std::string_view name) {
  return std::find(known_flags.begin(), known_flags.end(), name) != known_flags.end();
}

}  // namespace

bool wants_help(std::span<const std::string_view> arguments) {
  return std::any_of(arguments.begin(), arguments.end(),
                     [](std::string_view argument) { return argument == "--help" || argument == "-h"; });
}

std::vector<std::string_view> split_list(std::string_view text, char separator) {
  std::vector<std::string_view> items;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(separator, start);
    items.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return items;
    start = end + 1;
  }
}

ParsedFlags ParsedFlags::parse(std::span<const std::string_view> arguments,
                               std::span<const std::string_view> known_flags, std::string_view command,
                               std::span<const std::string_view> known_switches) {
  ParsedFlags flags;
  for (std::size_t index = 0; index < arguments.size(); ++index) {
    const std::string_view argument = arguments[index];
    const bool output_short = argument == kOutputShortFlag && is_known(known_flags, "output");
    if (!output_short && (!argument.starts_with(kFlagPrefix) || argument.size() == kFlagPrefix.size())) {
      throw UsageError("unexpected argument " + text::quoted(argument) + " for " + std::string(command) +
                       "; flags are written --name value or --name=value");
    }
    const std::string_view body = output_short ? std::string_view("output") : argument.substr(kFlagPrefix.size());
    const std::size_t equals = body.find('=');
    const std::string_view name = body.substr(0, equals);
    const bool is_switch = is_known(known_switches, name);
    if (!is_switch && !is_known(known_flags, name)) {
      throw UsageError("unknown flag " + text::quoted(argument.substr(0, kFlagPrefix.size() + name.size())) + " for " +
                       std::string(command) + "; see " + std::string(command) + " --help");
    }
    std::string_view value;
    if (is_switch) {
      if (equals != std::string_view::npos) {
        throw UsageError("flag --" + std::string(name) + " is a switch and takes no value; write --" +
                         std::string(name));
      }
    } else if (equals != std::string_view::npos) {
      value = body.substr(equals + 1);
    } else if (index + 1 < arguments.size() && !arguments[index + 1].starts_with(kFlagPrefix)) {
      value = arguments[++index];
    } else {
      throw UsageError("flag --" + std::string(name) + " needs a value");
    }
    if (flags.has(name) && !is_known(kRepeatableFlags, name)) {
      throw UsageError("flag --" + std::string(name) + " is given more than once");
    }
    flags.values_.emplace_back(name, value);
  }
  return flags;
}

std::optional<std::string_view> ParsedFlags::value(std::string_view name) const {
  for (const auto& [flag, value] : values_) {
    if (flag == name) return value;
  }
  return std::nullopt;
}

std::vector<std::string_view> ParsedFlags::values(std::string_view name) const {
  std::vector<std::string_view> result;
  for (const auto& [flag, value] : values_) {
    if (flag == name) result.push_back(value);
  }
  return result;
}

double number_flag(const ParsedFlags& flags, std::string_view name, double fallback, double low, double high,
                   std::string_view note) {
  const std::optional<std::string_view> text = flags.value(name);
  if (!text) return fallback;
  const std::optional<double> value = text::parse_number(*text);
  if (!value || !(*value >= low && *value <= high)) {
    throw UsageError(std::string(name) + " = " + text::quoted(*text) + " is out of range; valid range is [" +
                     text::format_short(low) + ", " + text::format_short(high) + "]" + std::string(note));
  }
  return *value;
}

}  // namespace skinlayer::cli
