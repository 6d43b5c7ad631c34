// The biophysical parameters of a two-layer skin (epidermis over a semi-infinite dermis), after Donner & Jensen
// 2006 ("A Spectral BSSRDF for Shading Human Skin", EGSR) and Jacques 2013 ("Optical properties of biological
// tissues: a review", Phys. Med. Biol. 58 R37): what `--skin KEY=VALUE,...` and a material file's "skin" block set.
// Fractions are volume fractions (dimensionless); the thickness is in mm.
#pragma once

#include <span>

#include "core/material.h"

namespace skinlayer {

struct SkinParameters {
  // Epidermal melanin (melanosome) volume fraction. Jacques 2013 Table 3 lists 1.65-2.5% for lightly pigmented
  // skin; Donner & Jensen's examples run from 0.5% (Caucasian) to 50% (African).
  double melanin = 0.02;
  double eumelanin = 0.7;     // the eumelanin share of the melanin (the rest pheomelanin); Donner & Jensen use 0.7
  double blood = 0.005;       // dermal blood volume fraction: 0.2% (Jacques 2013 Table 3) to 5% (Donner & Jensen)
  double oxygenation = 0.75;  // blood oxygen saturation S; Jacques 2013 uses 0.75 for mixed vasculature
  double epidermis = 0.06;    // epidermis thickness, mm (the 60 um convention of Jacques 2013's data page)
  double scattering = 1.0;    // a scale on both layers' reduced scattering coefficient

  bool operator==(const SkinParameters&) const = default;
};

// The table of the six parameters, in the order above, with their ranges and defaults (`flag` is the KEY).
std::span<const ParameterInfo> skin_parameter_table();
const ParameterInfo& skin_parameter_info(std::string_view key);
// The parameter's field in p.
double& skin_parameter(SkinParameters& p, std::string_view key);
double skin_parameter(const SkinParameters& p, std::string_view key);

// Throws ParameterError naming the first parameter out of its range (check_parameter's message).
void validate(const SkinParameters& skin);

}  // namespace skinlayer
