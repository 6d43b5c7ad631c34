// A Principled fit (core/fit/principled_fit.h) as JSON: what `skinlayer fit --target principled` writes, and what
// the exported Blender script carries beside its material. Errors are per channel, [red, green, blue].
#pragma once

#include <nlohmann/json.hpp>

#include "core/fit/principled_fit.h"

namespace skinlayer {

// {"target", "renderer", "parameters": {base_color, metallic, ...}, "albedo_matched_at_normal_incidence",
//  "albedo_miss_at_normal_incidence", "errors": {lobe_rms, lobe_worst, albedo_rms, albedo_worst}}.
nlohmann::ordered_json principled_fit_json(const PrincipledFit& fit);

}  // namespace skinlayer
