// The biophysical skin on the command line (issue 25): --skin KEY=VALUE[,KEY=VALUE...] with the keys of
// core/skin/skin_parameters.h (melanin, eumelanin, blood, oxygenation, epidermis, scattering); an omitted key keeps
// its value from `base` (the defaults, or a material file's). --wavelength NM picks one wavelength's grey material.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "app/cli/flag_parser.h"
#include "app/material/material_document.h"
#include "app/material/material_flag_text.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer::cli {

inline constexpr std::string_view kSkinFlag = "skin";
inline constexpr std::string_view kWavelengthFlag = "wavelength";

// Throws ParameterError ("skin: blood = 0.3 is out of range; valid range is [0, 0.2] (...)") for a value out of
// range or NaN, UsageError for an unknown or repeated key or a value that is not a number.
SkinParameters parse_skin_spec(std::string_view text, const SkinParameters& base = {});

// --wavelength's value in nm, in [360, 830] (where the colour tables are defined; the hemoglobin table reaches
// 250-1000 nm); none when the flag is absent.
std::optional<double> wavelength_from_flags(const ParsedFlags& flags);

// The document at one wavelength: a skin's layers there, as a grey document; a grey document as it is (its spectrum
// is flat). An RGB document has no spectrum: UsageError.
MaterialDocument document_at_wavelength(const MaterialDocument& document, double wavelength_nm);

// The help lines of --skin (and of --wavelength where the command takes it), with every key's range and default.
std::string skin_flags_usage(bool with_wavelength = true);

}  // namespace skinlayer::cli
