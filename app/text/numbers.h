// Strict conversion between numbers and text: for the command line and its CSV, and for every room that writes
// numbers into text (exports, figures, the previewer's scripted edits).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace skinlayer::text {

// Parses the whole token as a double with std::from_chars (general format): no leading '+', no surrounding
// whitespace, no trailing characters. "nan" and "inf" (any case) are accepted here; callers decide whether a
// non-finite value is allowed. Returns nullopt for anything else, including well-formed numbers whose magnitude a
// double cannot hold: above 1.8e308 (overflow) or nonzero below 4.9e-324 (underflow).
std::optional<double> parse_number(std::string_view token);

// Why parse_number rejects a token, as the end of an error message ("sigma = '1e-400' " + this): "is not a number",
// or for a well-formed number out of a double's range "is too large for a double (magnitude above 1.8e308)" or
// "is too small for a double (nonzero magnitude below 4.9e-324)".
std::string number_rejection(std::string_view token);

// Formats a value with printf "%.17g": enough digits to read back the same double.
std::string format_number(double value);

// Formats a value in the shortest form that reads back as the same double (std::to_chars), e.g. 0.1 as "0.1".
std::string format_shortest(double value);

// step times i as the decimal a person would write: to 12 significant digits, so that 3 x 0.2 is 0.6, not
// 0.6000000000000001 (a grid of annulus edges, radii, angles; the value moves by 1e-16 relative at most).
double decimal_multiple(double step, int i);

// Formats a value with printf "%.10g" (as core does), for ranges and defaults in help and error text.
std::string format_short(double value);

}  // namespace skinlayer::text
