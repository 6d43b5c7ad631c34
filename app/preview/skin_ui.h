// The previewer's Skin section (issue 25): a material made from its chromophores (core/skin/skin_parameters.h)
// instead of its layers' optical parameters, with the six sliders live, and the "Match colour..." picker that sets
// the parameters from a picked colour. ImGui must be inside a frame and a window.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "app/solution/material_solve.h"

namespace skinlayer {

struct SkinSectionInput {
  bool matching = false;  // a match runs: the picker's button waits
  std::string outcome;    // the last match's outcome, shown under the picker; empty: none
};

struct SkinSectionResult {
  bool changed = false;                             // a slider moved, or the material became (or left) a skin
  std::optional<std::array<double, 3>> match_srgb;  // "Match" pressed: the picked colour, sRGB-encoded, in [0, 1]
};

// For a skin: the six sliders and "Use layers instead"; for a layered material: "Make it a skin" (the default skin
// under the same top interface). Both: the picker, whose colour lives in `picked` (sRGB-encoded) between frames.
SkinSectionResult skin_section(ColorMaterial& material, std::array<float, 3>& picked, const SkinSectionInput& input);

}  // namespace skinlayer
