// User-supplied text made safe to embed in a one-line error message.
#pragma once

#include <string>
#include <string_view>

namespace skinlayer::text {

// The text with every control character (U+0000-U+001F, U+007F) and every byte that is not part of well-formed
// UTF-8 (RFC 3629: no overlong forms, surrogates or code points past U+10FFFF) shown as '?': one line of valid
// UTF-8, fit for a terminal and for Python's str.
std::string printable(std::string_view text);

// printable(text) in single quotes, anything past 40 bytes cut to "...".
std::string quoted(std::string_view text);

}  // namespace skinlayer::text
