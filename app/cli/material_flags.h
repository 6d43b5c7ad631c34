// The material flags shared by the solving commands, read into a skinlayer::Material against core's parameter
// table: --sigma --eta --T | --tau --albedo --g --bottom air|matched|lambert:A [--bottom-sigma --bottom-eta]
// [--ordinates N].
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <initializer_list>
#include <vector>

#include "app/cli/flag_parser.h"
#include "core/material.h"

namespace skinlayer::cli {

// The material flag names, without dashes.
std::span<const std::string_view> material_flag_names();

// The material flag names followed by a command's own flags.
std::vector<std::string_view> material_flags_and(std::initializer_list<std::string_view> own_flags);

// Builds the material from the flags; an omitted flag keeps skinlayer::Material{}'s default.
// Throws skinlayer::ParameterError (core's check_parameter message: names the parameter and its range) for a value
// out of range or NaN, and UsageError for a value that is not a number, --T together with --tau, --bottom-sigma or
// --bottom-eta with a bottom other than air, or a non-integer --ordinates.
Material material_from_flags(const ParsedFlags& flags);

// The flags that material_from_flags reads back into the same material: every parameter, e.g.
// "--sigma 0.5 --eta 1.4 --T 0.2 --albedo 1 --g 0.8 --bottom air" (--tau when T would not read back exactly; the
// bottom's own sigma and eta and --ordinates only when set), each number in its shortest exact form.
std::string material_to_flags(const Material& material);

// Help text for the material flags: every flag with its meaning, symbol, range and default, from
// skinlayer::parameter_table().
std::string material_flags_usage();

}  // namespace skinlayer::cli
