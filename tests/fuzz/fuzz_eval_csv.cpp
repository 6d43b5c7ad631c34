// Fuzz target: the rows of direction pairs that `skinlayer eval` reads on stdin (app/cli/csv_reader.h). Rows that
// read lie in range: theta_i, theta_o in [0, 90], phi finite.
#include <cmath>
#include <sstream>

#include "app/cli/csv_reader.h"
#include "app/cli/errors.h"
#include "tests/fuzz/fuzz_target.h"

using namespace skinlayer;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in{std::string(fuzz::input_bytes(data, size))};
  std::vector<cli::AngleRow> rows;
  if (fuzz::refused_cleanly<cli::InputError>([&] { rows = cli::read_angle_rows(in); })) return 0;
  fuzz::require(!rows.empty(), "no rows read without an error");
  for (const cli::AngleRow& row : rows) {
    fuzz::require(row.theta_i >= 0.0 && row.theta_i <= 90.0 && row.theta_o >= 0.0 && row.theta_o <= 90.0 &&
                      std::isfinite(row.phi),
                  "a row out of range was read");
  }
  return 0;
}
