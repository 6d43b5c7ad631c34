// User-supplied text made safe to embed in a one-line error message.
#pragma once

#include <string>
#include <string_view>

namespace skinlayer::cli {

// Returns text in single quotes, with control characters shown as '?' and anything past 40 characters cut to "...".
std::string quoted(std::string_view text);

}  // namespace skinlayer::cli
