// Command-line flags of the form "--name value" or "--name=value", checked against the flags a command accepts.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace skinlayer::cli {

// True when any argument is "--help" or "-h".
bool wants_help(std::span<const std::string_view> arguments);

// The items of a list-valued flag ("0,30,60", "0.9,0.6,0.5"): the text split at every separator, empty items kept
// ("" is one empty item, "a," is "a" and ""), views into `text`.
std::vector<std::string_view> split_list(std::string_view text, char separator);

// The flags given to one command, by name without the dashes: each at most once, but for the repeatable ones
// (kRepeatableFlags: --layer), which keep every value in order.
inline constexpr std::string_view kRepeatableFlags[] = {"layer"};

class ParsedFlags {
 public:
  // "-o FILE" is read as "--output FILE" when "output" is a known flag. A switch ("--quick") takes no value; has()
  // tells whether it was given.
  // Throws UsageError, naming the argument, for: an argument that is not a flag, a flag not in known_flags or
  // known_switches, a flag with no value (end of arguments, or the next argument starts with "--"), a switch given a
  // value ("--quick=1"), or a flag or switch given twice (but a repeatable flag).
  // command names the command in messages, e.g. "skinlayer eval".
  static ParsedFlags parse(std::span<const std::string_view> arguments, std::span<const std::string_view> known_flags,
                           std::string_view command, std::span<const std::string_view> known_switches = {});

  bool has(std::string_view name) const { return value(name).has_value(); }
  // The flag's value (the first, for a repeatable flag), or nullopt.
  std::optional<std::string_view> value(std::string_view name) const;
  // Every value of a flag in command-line order (empty when absent).
  std::vector<std::string_view> values(std::string_view name) const;

 private:
  std::vector<std::pair<std::string, std::string>> values_;  // (name, value) in command-line order
};

// The number a flag gives, or `fallback` when it is absent. Throws UsageError "<name> = '<text>' is out of range;
// valid range is [low, high]<note>" for a value that is not a number in [low, high].
double number_flag(const ParsedFlags& flags, std::string_view name, double fallback, double low, double high,
                   std::string_view note);

}  // namespace skinlayer::cli
