#include "app/cli/numeric_table.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "app/text/numbers.h"

namespace skinlayer::cli {

NumericTable::NumericTable(std::vector<std::string> input_columns, std::vector<std::string> computed_columns)
    : columns_(std::move(input_columns)), input_columns_(columns_.size()) {
  columns_.insert(columns_.end(), computed_columns.begin(), computed_columns.end());
}

void NumericTable::add_row(const std::vector<double>& values) {
  if (values.size() != columns_.size()) throw std::logic_error("NumericTable::add_row: wrong number of values");
  values_.insert(values_.end(), values.begin(), values.end());
}

std::size_t NumericTable::rows() const { return columns_.empty() ? 0 : values_.size() / columns_.size(); }

void NumericTable::require_finite() const {
  for (std::size_t index = 0; index < values_.size(); ++index) {
    if (!std::isfinite(values_[index])) {
      const std::size_t row = index / columns_.size() + 1;
      throw std::runtime_error("output row " + std::to_string(row) + ": " + columns_[index % columns_.size()] + " = " +
                               text::format_number(values_[index]) + " is not finite; no output was written");
    }
  }
}

void NumericTable::write_csv(std::ostream& out) const {
  std::string text;
  for (std::size_t column = 0; column < columns_.size(); ++column) {
    if (column > 0) text += ',';
    text += columns_[column];
  }
  text += '\n';
  for (std::size_t index = 0; index < values_.size(); ++index) {
    const bool is_input = index % columns_.size() < input_columns_;
    text += is_input ? text::format_shortest(values_[index]) : text::format_number(values_[index]);
    text += (index + 1) % columns_.size() == 0 ? '\n' : ',';
  }
  out << text;
  out.flush();
  if (!out) throw std::runtime_error("could not write the output");
}

std::vector<std::string> channel_columns(std::string_view name) {
  std::vector<std::string> columns;
  for (const char* suffix : {"_r", "_g", "_b"}) columns.push_back(std::string(name) + suffix);
  return columns;
}

}  // namespace skinlayer::cli
