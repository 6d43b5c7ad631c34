// A material written as the command line's text, which its parsers (app/cli: layer_flag.h, skin_flag.h,
// material_flags.h) read back into the same material: what material files, figures, reports and plots print so that
// a user can repeat them. Writing only: below the command line, so that those rooms need not include it.
#pragma once

#include <string>

#include "app/material/material_document.h"
#include "core/material.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer {

// The spec that cli::parse_layer_spec reads back into the same layer
// ("T=0.5,albedo=0.9,g=0.8[,mu_t=..][,sigma=..,eta=..]").
std::string format_layer_spec(const StackedLayer& layer, const AlbedoRgb& albedo);

// The spec that cli::parse_skin_spec reads back into the same parameters ("melanin=0.02,eumelanin=0.7,...").
std::string format_skin_spec(const SkinParameters& skin);

// The flags that cli::material_from_flags reads back into the same material: every parameter, e.g.
// "--sigma 0.5 --eta 1.4 --T 0.2 --albedo 1 --g 0.8 --bottom air" (--tau when T would not read back exactly; the
// bottom's own sigma and eta and --ordinates only when set), each number in its shortest exact form.
std::string material_to_flags(const Material& material);

}  // namespace skinlayer
