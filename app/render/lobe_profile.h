// The subsurface tables in the plane of incidence at one incident angle, as the lobe plot draws them (pure CPU data).
#pragma once

#include <vector>

#include "app/render/table_textures.h"

namespace skinlayer {

// Rows of the lobe plot's profile texture (RGBA32F, one column per table texel, linear filtering, clamp to edge).
enum class LobeProfileRow { ReflectionBackward, ReflectionForward, TransmissionBackward, TransmissionForward };
inline constexpr int kLobeProfileRows = 4;

// The tables' texels interpolated to theta_i across rows exactly as the GPU's bilinear filter does (texture
// coordinate of shaders/table_layout.h), and their Fourier modes summed at phi = 0 (backward) and phi = pi (forward):
// sum_m c_m cos(m phi) is linear in the texels, so a linear fetch from this profile equals the per-mode bilinear
// fetches summed, and the plot reads one texel pair per pixel instead of every mode's. Not clamped: the shader clamps
// the sum at 0 as it does for the tables. Layout [row][column][RGBA], tables.size columns.
std::vector<float> lobe_profile(const TableTextureData& tables, double theta_i);

}  // namespace skinlayer
