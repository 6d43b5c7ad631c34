#include "app/cli/model_flag.h"

#include <optional>
#include <string>

#include "app/cli/errors.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {

SubsurfaceModel model_from_flags(const ParsedFlags& flags, std::optional<SubsurfaceModel> fallback) {
  const std::optional<std::string_view> text = flags.value(kModelFlag);
  if (!text) return fallback.value_or(SubsurfaceModel::Stam);
  const std::optional<SubsurfaceModel> model = parse_subsurface_model(*text);
  if (!model) {
    throw UsageError("model = " + text::quoted(*text) +
                     " is not one of stam (the layer model), lambert, hk (Hanrahan-Krueger single scattering)");
  }
  return *model;
}

}  // namespace skinlayer::cli
