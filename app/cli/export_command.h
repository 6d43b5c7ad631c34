// `skinlayer export --format merl [material flags | --material F | --preset P] [--albedo A | r,g,b] [--model M]
// -o FILE`: the solved material in a tabulated format another program reads (issue 13). merl: the MERL BRDF
// ".binary" (app/export/merl_brdf.h), reflection only. Progress goes to stderr; the file is written atomically.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string export_usage();
int run_export_command(std::span<const std::string_view> arguments, std::ostream& out, std::ostream& progress);

}  // namespace skinlayer::cli
