// A table of numbers with named columns, checked for finiteness and written as CSV. The leading columns echo the
// user's input and are written in the shortest form that reads back exactly ("30.5", "0.1"); the computed columns
// are written with "%.17g" (up to 17 significant digits).
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace skinlayer::cli {

class NumericTable {
 public:
  NumericTable(std::vector<std::string> input_columns, std::vector<std::string> computed_columns);

  // Appends one row. Throws std::logic_error unless it has one value per column.
  void add_row(const std::vector<double>& values);

  std::size_t rows() const;

  // Throws std::runtime_error naming the row (from 1) and column of the first NaN or infinite value.
  void require_finite() const;

  // Writes the header line and every row, then flushes. Throws std::runtime_error if the stream fails.
  void write_csv(std::ostream& out) const;

 private:
  std::vector<std::string> columns_;  // input columns, then computed columns
  std::size_t input_columns_ = 0;
  std::vector<double> values_;  // row-major
};

// The columns of a quantity that depends on colour, one per channel: name_r, name_g, name_b.
std::vector<std::string> channel_columns(std::string_view name);

}  // namespace skinlayer::cli
