// Reading the command line's CSV output back in tests.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace skinlayer::test {

// The text split into lines at '\n' (a final '\n' ends the last line, it does not start an empty one).
std::vector<std::string> split_lines(std::string_view text);

// A line split at commas.
std::vector<std::string> split_fields(std::string_view line);

// The whole field as a double; throws std::invalid_argument if it is not a number.
double to_number(std::string_view field);

// The number of significant digits written in a decimal number such as "-0.012340e-5": the digits of the mantissa
// from the first non-zero one on.
int significant_digits(std::string_view number);

// A parsed CSV output: header fields and numeric rows. Throws std::invalid_argument for a non-numeric field or a row
// whose length differs from the header's.
struct CsvOutput {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::vector<std::vector<std::string>> row_texts;
};
CsvOutput parse_csv_output(std::string_view text);

}  // namespace skinlayer::test
