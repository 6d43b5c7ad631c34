// --model stam|lambert|hk: which subsurface model a command evaluates (core/models/subsurface_model.h). Default stam.
#pragma once

#include <optional>
#include <string_view>

#include "app/cli/flag_parser.h"
#include "core/models/subsurface_model.h"

namespace skinlayer::cli {

inline constexpr std::string_view kModelFlag = "model";

// --model's value, else `fallback` (a material file's model), else stam. Throws UsageError naming the flag and its
// choices for an unknown model.
SubsurfaceModel model_from_flags(const ParsedFlags& flags, std::optional<SubsurfaceModel> fallback = std::nullopt);

}  // namespace skinlayer::cli
