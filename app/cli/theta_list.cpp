#include "app/cli/theta_list.h"

#include <optional>
#include <string>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {

std::vector<double> parse_theta_list(std::string_view list) {
  std::vector<double> thetas;
  for (const std::string_view item : split_list(list, ',')) {
    const std::optional<double> value = text::parse_number(item);
    if (!value) {
      throw UsageError(std::string(kThetaFlag) + " = " + text::quoted(item) + " " + text::number_rejection(item) +
                       "; give a comma-separated list of angles in [0, 90] degrees, as in "
                       "--theta-i 0,30,60,80");
    }
    if (!(*value >= 0.0 && *value <= 90.0)) {
      throw UsageError(std::string(kThetaFlag) + " = " + text::format_number(*value) +
                       " is out of range; valid range is [0, 90] (degrees)");
    }
    thetas.push_back(*value);
  }
  return thetas;
}

}  // namespace skinlayer::cli
