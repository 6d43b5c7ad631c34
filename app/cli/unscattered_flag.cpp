#include "app/cli/unscattered_flag.h"

#include <optional>
#include <string>

#include "app/cli/errors.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {

UnscatteredLobe unscattered_lobe_named(std::string_view text) {
  const std::optional<UnscatteredLobe> lobe = parse_unscattered_lobe(text);
  if (!lobe)
    throw UsageError("unscattered = " + text::quoted(text) + " is not one of " + std::string(kUnscatteredLobeChoices));
  return *lobe;
}

UnscatteredLobe unscattered_lobe_from_flags(const ParsedFlags& flags) {
  const std::optional<std::string_view> text = flags.value(kUnscatteredFlag);
  return text ? unscattered_lobe_named(*text) : UnscatteredLobe::Auto;
}

}  // namespace skinlayer::cli
