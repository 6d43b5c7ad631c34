#include "tests/app/csv_output.h"

#include <cctype>
#include <charconv>
#include <stdexcept>

namespace skinlayer::test {

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> lines;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    lines.emplace_back(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return lines;
}

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  while (true) {
    const std::size_t comma = line.find(',');
    fields.emplace_back(line.substr(0, comma));
    if (comma == std::string_view::npos) return fields;
    line.remove_prefix(comma + 1);
  }
}

double to_number(std::string_view field) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || error != std::errc() || end != field.data() + field.size()) {
    throw std::invalid_argument("not a number: '" + std::string(field) + "'");
  }
  return value;
}

int significant_digits(std::string_view number) {
  const std::size_t exponent = number.find_first_of("eE");
  const std::string_view mantissa = number.substr(0, exponent);
  int digits = 0;
  bool leading = true;
  for (const char c : mantissa) {
    if (std::isdigit(static_cast<unsigned char>(c)) == 0) continue;
    if (leading && c == '0') continue;
    leading = false;
    ++digits;
  }
  return digits;
}

CsvOutput parse_csv_output(std::string_view text) {
  CsvOutput output;
  const std::vector<std::string> lines = split_lines(text);
  if (lines.empty()) return output;
  output.header = split_fields(lines.front());
  for (std::size_t index = 1; index < lines.size(); ++index) {
    std::vector<std::string> fields = split_fields(lines[index]);
    if (fields.size() != output.header.size()) {
      throw std::invalid_argument("row " + std::to_string(index) + " has " + std::to_string(fields.size()) +
                                  " fields, the header " + std::to_string(output.header.size()));
    }
    std::vector<double> values;
    for (const std::string& field : fields) values.push_back(to_number(field));
    output.rows.push_back(std::move(values));
    output.row_texts.push_back(std::move(fields));
  }
  return output;
}

}  // namespace skinlayer::test
