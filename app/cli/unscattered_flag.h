// --unscattered auto|exact|table: how eval evaluates the light that crosses two rough interfaces unscattered
// (app/solution/pair_evaluation.h's UnscatteredLobe). Default auto.
#pragma once

#include <string_view>

#include "app/cli/flag_parser.h"
#include "app/solution/pair_evaluation.h"

namespace skinlayer::cli {

inline constexpr std::string_view kUnscatteredFlag = "unscattered";

// The choice named `text`. Throws UsageError naming the parameter and its choices for anything else.
UnscatteredLobe unscattered_lobe_named(std::string_view text);
// --unscattered's value, else auto.
UnscatteredLobe unscattered_lobe_from_flags(const ParsedFlags& flags);

}  // namespace skinlayer::cli
