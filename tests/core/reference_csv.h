// Reads the reference tables in tests/reference/ as data (their provenance is in tests/reference/README.md).
#pragma once

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace skinlayer::test {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return static_cast<int>(i);
    }
    throw std::runtime_error("no column " + name);
  }
  double number(std::size_t row, const std::string& name) const { return std::stod(rows[row][column(name)]); }
  const std::string& text(std::size_t row, const std::string& name) const { return rows[row][column(name)]; }
};

inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.push_back(field);
      field.clear();
    } else if (c != '\r') {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}

inline CsvTable read_reference(const std::string& name) {
  const std::string path = std::string(SKINLAYER_REFERENCE_DIR) + "/" + name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open reference table " + path);
  CsvTable table;
  std::string line;
  std::getline(in, line);
  table.header = split_csv_line(line);
  while (std::getline(in, line)) {
    if (!line.empty()) table.rows.push_back(split_csv_line(line));
  }
  return table;
}

}  // namespace skinlayer::test
