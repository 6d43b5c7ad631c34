#include "app/cli/csv_reader.h"

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "app/cli/errors.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {
namespace {

constexpr std::size_t kColumns = 3;
constexpr std::array<std::string_view, kColumns> kColumnNames = {"theta_i", "theta_o", "phi"};
constexpr double kMaxPolarDegrees = 90.0;

std::string_view trim_blanks(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const std::size_t last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

// The line's comma-separated fields, trimmed; more than kColumns fields are reported by count only.
struct SplitLine {
  std::array<std::string_view, kColumns> fields{};
  std::size_t count = 0;
};

SplitLine split_fields(std::string_view line) {
  SplitLine split;
  while (true) {
    const std::size_t comma = line.find(',');
    if (split.count < kColumns) split.fields[split.count] = trim_blanks(line.substr(0, comma));
    ++split.count;
    if (comma == std::string_view::npos) return split;
    line.remove_prefix(comma + 1);
  }
}

bool is_header(const SplitLine& split) { return split.count == kColumns && split.fields == kColumnNames; }

std::string at_line(std::size_t line_number) { return "line " + std::to_string(line_number) + ": "; }

double parse_angle(std::string_view field, std::size_t column, std::size_t line_number) {
  const std::string name(kColumnNames[column]);
  const std::optional<double> value = text::parse_number(field);
  if (!value) {
    throw InputError(at_line(line_number) + name + " = " + text::quoted(field) + " " + text::number_rejection(field));
  }
  const bool is_polar = column < 2;
  if (is_polar && !(*value >= 0.0 && *value <= kMaxPolarDegrees)) {
    throw InputError(at_line(line_number) + name + " = " + text::format_number(*value) +
                     " is out of range; valid range is [0, 90] (degrees)");
  }
  if (!std::isfinite(*value)) {
    throw InputError(at_line(line_number) + name + " = " + text::format_number(*value) +
                     " is not finite; phi may be any finite number (degrees)");
  }
  return *value;
}

}  // namespace

std::vector<AngleRow> read_angle_rows(std::istream& in) {
  std::vector<AngleRow> rows;
  std::string text;
  for (std::size_t line_number = 1; std::getline(in, text); ++line_number) {
    std::string_view line = text;
    if (line.ends_with('\r')) line.remove_suffix(1);
    if (trim_blanks(line).empty()) {
      throw InputError(at_line(line_number) + "blank line; every line must be a row theta_i,theta_o,phi");
    }
    const SplitLine split = split_fields(line);
    if (line_number == 1 && is_header(split)) continue;
    if (split.count != kColumns) {
      throw InputError(at_line(line_number) + "expected 3 fields theta_i,theta_o,phi but found " +
                       std::to_string(split.count) + " in " + text::quoted(line));
    }
    rows.push_back({parse_angle(split.fields[0], 0, line_number), parse_angle(split.fields[1], 1, line_number),
                    parse_angle(split.fields[2], 2, line_number)});
  }
  if (in.bad()) throw InputError("could not read stdin");
  if (rows.empty()) {
    throw InputError(
        "no data rows on stdin; expected CSV rows theta_i,theta_o,phi in degrees (after an optional "
        "header line)");
  }
  return rows;
}

}  // namespace skinlayer::cli
