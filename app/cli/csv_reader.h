// The rows of direction pairs that `skinlayer eval` reads from CSV: theta_i,theta_o,phi in degrees.
//
// Format, strict:
//   * One row per line: exactly three comma-separated numbers theta_i,theta_o,phi (no quoting). Numbers are read
//     whole with std::from_chars: "30", "-12.5", "1e1"; not "+30", "30deg" or "".
//   * Spaces and tabs around a field are ignored, and so is a trailing CR (CRLF line ends).
//   * Only the first line may instead be the header theta_i,theta_o,phi.
//   * A blank line (empty, or only spaces and tabs) is malformed, like any other bad row: rows are never skipped.
//     A final line end after the last row does not make a blank line.
//   * theta_i and theta_o must lie in [0, 90]; phi may be any finite number.
#pragma once

#include <istream>
#include <vector>

namespace skinlayer::cli {

struct AngleRow {
  double theta_i;  // degrees
  double theta_o;  // degrees
  double phi;      // degrees
};

// Reads every row to the end of the stream. Throws InputError for the first malformed line, naming its line number
// (from 1) and, for a bad value, its column and valid range; and for input with no data rows.
std::vector<AngleRow> read_angle_rows(std::istream& in);

}  // namespace skinlayer::cli
