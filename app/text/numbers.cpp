#include "app/text/numbers.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <system_error>

namespace skinlayer::text {

std::optional<double> parse_number(std::string_view token) {
  double value = 0.0;
  const char* const end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  if (token.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

std::string number_rejection(std::string_view token) {
  double value = 0.0;
  const char* const end = token.data() + token.size();
  const auto [stop, error] = std::from_chars(token.data(), end, value);
  if (token.empty() || error != std::errc::result_out_of_range || stop != end) return "is not a number";
  // from_chars leaves the value unset on a range error; strtod (the token is well-formed) rounds it to +-HUGE_VAL
  // on overflow and to at most DBL_MIN in magnitude on underflow.
  const double rounded = std::strtod(std::string(token).c_str(), nullptr);
  return std::abs(rounded) > 1.0 ? "is too large for a double (magnitude above 1.8e308)"
                                 : "is too small for a double (nonzero magnitude below 4.9e-324)";
}

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string format_shortest(double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (error != std::errc()) return format_number(value);
  return std::string(buffer, end);
}

std::string format_short(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

double decimal_multiple(double step, int i) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", step * i);
  return std::strtod(text, nullptr);
}

}  // namespace skinlayer::text
