// export's own flags: --format bsdf|merl|rgl [--nodes N] [--rgb] [--resolution N], read into ExportSettings
// (app/export/material_export.h). The command line and the Python module's Solution.export read them alike.
#pragma once

#include <span>
#include <string_view>

#include "app/cli/flag_parser.h"
#include "app/export/material_export.h"

namespace skinlayer::cli {

// The flags and switches below, without dashes.
std::span<const std::string_view> export_flag_names();    // format, nodes, resolution
std::span<const std::string_view> export_switch_names();  // rgb

// The settings the flags ask for (description left empty). Throws UsageError naming the flag: no --format or an
// unknown one, --nodes that is not a whole number in [kMinScatfunNodes, kMaxScatfunNodes] or not with bsdf,
// --resolution not a whole number in [RglOptions::kMinSamples, kMaxSamples] or not with rgl, --rgb not with rgl.
ExportSettings export_settings_from_flags(const ParsedFlags& flags);

}  // namespace skinlayer::cli
