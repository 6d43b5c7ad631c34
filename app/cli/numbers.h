// Strict conversion between numbers and text for the command line and its CSV.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace skinlayer::cli {

// Parses the whole token as a double with std::from_chars (general format): no leading '+', no surrounding
// whitespace, no trailing characters. "nan" and "inf" (any case) are accepted here; callers decide whether a
// non-finite value is allowed. Returns nullopt for anything else, including values that overflow a double.
std::optional<double> parse_number(std::string_view token);

// Formats a value with printf "%.17g": enough digits to read back the same double.
std::string format_number(double value);

// Formats a value in the shortest form that reads back as the same double (std::to_chars), e.g. 0.1 as "0.1".
std::string format_shortest(double value);

// Formats a value with printf "%.10g" (as core does), for ranges and defaults in help and error text.
std::string format_short(double value);

}  // namespace skinlayer::cli
