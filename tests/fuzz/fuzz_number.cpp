// Fuzz target: the strict number parser of the command line and its CSV (app/text/numbers.h). A number that reads
// formats back to the same double in both of its forms; a token that does not gets a one-line reason.
#include <cmath>
#include <cstring>

#include "app/text/numbers.h"
#include "tests/fuzz/fuzz_target.h"

using namespace skinlayer;

namespace {

bool same_double(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view token = fuzz::input_bytes(data, size);
  const std::optional<double> value = text::parse_number(token);
  if (!value) {
    fuzz::require_one_line("x = '' " + text::number_rejection(token));
    return 0;
  }
  if (std::isnan(*value)) return 0;  // "nan" reads; its sign and payload are not kept
  for (const std::string& text : {text::format_number(*value), text::format_shortest(*value)}) {
    const std::optional<double> again = text::parse_number(text);
    fuzz::require(again && same_double(*again, *value), "a number does not read back once formatted: " + text);
  }
  return 0;
}
