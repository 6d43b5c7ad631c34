// The material flags shared by the solving commands, read into a skinlayer::Material against core's parameter
// table: [--material FILE | --preset NAME] --sigma --eta (--T | --tau --albedo --g | --layer SPEC...)
// --bottom air|matched|lambert:A [--bottom-sigma --bottom-eta] [--ordinates N]. --layer (app/cli/layer_flag.h),
// repeated, gives a stack top to bottom and replaces the file's layers.
#pragma once

#include <array>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli/flag_parser.h"
#include "app/material/material_document.h"
#include "app/material/material_flag_text.h"
#include "core/material.h"

namespace skinlayer::cli {

// The material flag names, without dashes (the parameters; not --material and --preset).
std::span<const std::string_view> material_flag_names();

// The material flag names and the source flags (--material FILE, --preset NAME: where the material starts before
// its flags apply), followed by a command's own flags.
std::vector<std::string_view> material_flags_and(std::initializer_list<std::string_view> own_flags);

// How a command takes --albedo: one number, or also three "r,g,b" (render and the previewer).
enum class AlbedoFlag { Grey, GreyOrRgb };

// The material the flags describe: --material FILE (a material file or a skinlayer PNG) or --preset NAME, else
// skinlayer's defaults; then every material flag given, over it (flags win over the file). The document keeps the
// file's name, description and model (--model is the command's to read: model_from_flags).
// Throws skinlayer::ParameterError (core's check_parameter message: names the parameter and its range) for a value
// out of range or NaN, its message starting "layer <i>: " for a --layer value; UsageError for a value that is not a
// number, --T, --tau, --albedo or --g together with --layer, --T together with --tau, --material together
// with --preset, --bottom-sigma or --bottom-eta with a bottom other than air, or a non-integer --ordinates; and
// MaterialFileError for a file or preset that cannot be read.
MaterialDocument material_document_from_flags(const ParsedFlags& flags, AlbedoFlag albedo = AlbedoFlag::Grey);

// The document's layer, for the commands that solve one albedo. An RGB albedo (from a file, with no --albedo to
// replace it) is a UsageError that says so.
Material single_channel(const MaterialDocument& document);

// single_channel(material_document_from_flags(flags)).
Material material_from_flags(const ParsedFlags& flags);

// "A" or "r,g,b", each a single-scattering albedo in [0, 1]: ParameterError out of range, UsageError otherwise.
std::array<double, 3> albedo_rgb_from_text(std::string_view text);

// --microfacet's value, "multiple" or "single"; UsageError naming the flag and both values otherwise.
MicrofacetModel microfacet_from_text(std::string_view text);

// The help line of --albedo where it takes RGB: "  --albedo A | r,g,b   ..." with its range and default.
std::string rgb_albedo_usage();

// Help text for the material flags: every flag with its meaning, symbol, range and default, from
// skinlayer::parameter_table().
std::string material_flags_usage();

}  // namespace skinlayer::cli
