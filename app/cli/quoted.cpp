#include "app/cli/quoted.h"

namespace skinlayer::cli {

std::string quoted(std::string_view text) {
  constexpr std::size_t kMaxShown = 40;
  const bool cut = text.size() > kMaxShown;
  if (cut) text = text.substr(0, kMaxShown);
  std::string result = "'";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    result += (byte < 0x20 || byte == 0x7f) ? '?' : c;
  }
  result += cut ? "...'" : "'";
  return result;
}

}  // namespace skinlayer::cli
