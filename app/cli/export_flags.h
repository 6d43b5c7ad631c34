// export's own flags: --format bsdf|merl|rgl [--nodes N] [--rgb] [--resolution N], read into ExportSettings
// (app/export/material_export.h), or --format blender [--scene] | mtlx, read into FittedExportSettings
// (app/export/fitted_export.h). The command line and the Python module's Solution.export read them alike.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "app/cli/flag_parser.h"
#include "app/export/fitted_export.h"
#include "app/export/material_export.h"

namespace skinlayer::cli {

// The flags and switches below, without dashes.
std::span<const std::string_view> export_flag_names();    // format, nodes, resolution
std::span<const std::string_view> export_switch_names();  // rgb, scene

// A tabulated format's settings or a fitted shader's.
using ExportRequest = std::variant<ExportSettings, FittedExportSettings>;

// The settings the flags ask for (a tabulated format's description left empty). Throws UsageError naming the flag:
// no --format or an unknown one, --nodes that is not a whole number in [kMinScatfunNodes, kMaxScatfunNodes] or not
// with bsdf, --resolution not a whole number in [RglOptions::kMinSamples, kMaxSamples] or not with rgl, --rgb not
// with rgl, --scene not with blender.
ExportRequest export_request_from_flags(const ParsedFlags& flags);

// "cannot write PATH: no folder DIR" when the file's folder does not exist, found before the seconds of work, not
// after; nothing when it does (or PATH names no folder). Each caller throws it as its own kind of error.
std::optional<std::string> missing_output_folder(const std::string& path);

}  // namespace skinlayer::cli
