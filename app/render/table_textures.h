// The subsurface tables resampled into the GPU layout of shaders/table_layout.h (pure CPU data; no GL here, so the
// solve worker can build it off the UI thread).
#pragma once

#include <vector>

#include "app/solution/material_solve.h"
#include "core/unscattered/unscattered_light.h"

namespace skinlayer {

struct TableTextureData {
  int size = 0;                     // texels per axis
  int modes = 0;                    // layers
  std::vector<float> reflection;    // [mode][row = theta_i][column = theta_o][RGBA]
  std::vector<float> transmission;  // same layout
  UnscatteredLight unscattered;     // not in the textures: the shaders evaluate it (shaders/unscattered.glsl)
};

TableTextureData make_table_textures(const ColorTables& tables);

}  // namespace skinlayer
