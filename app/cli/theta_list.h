// --theta-i LIST, the incidence angles of the commands that tabulate energy fractions (albedo, spectrum).
#pragma once

#include <string_view>
#include <vector>

namespace skinlayer::cli {

inline constexpr std::string_view kThetaFlag = "theta-i";
inline constexpr std::string_view kDefaultThetas = "0,30,60,80";

// The comma-separated list of incidence angles in degrees, each a number in [0, 90]. Throws UsageError otherwise.
std::vector<double> parse_theta_list(std::string_view list);

}  // namespace skinlayer::cli
