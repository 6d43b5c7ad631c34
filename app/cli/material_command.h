// `skinlayer material [material flags | --material F | --preset P] [--albedo A | r,g,b] [--model M] [--name N]
// [--description D] [-o FILE]`: the complete material as a material file (app/material/material_json.h), every
// value explicit, to FILE (written atomically) or to stdout. Reading it back gives the same material bit for bit.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace skinlayer::cli {

std::string material_usage();
int run_material_command(std::span<const std::string_view> arguments, std::ostream& out);

// `skinlayer presets`: every preset's name and description, one per line.
std::string presets_usage();
int run_presets_command(std::span<const std::string_view> arguments, std::ostream& out);

}  // namespace skinlayer::cli
