// The previewer's one export path: read a rectangle of the bound framebuffer (the window's back buffer, before the
// swap) and write it as PNG. The S key, the Save button and --capture all go through save_screenshot(), with the
// picture's material and drawing_settings() in its text chunks.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/material/png_codec.h"
#include "app/preview/preview_state.h"
#include "app/render/renderer.h"

namespace skinlayer {

struct SavedScreenshot {
  std::string path;
  int width = 0;  // framebuffer pixels
  int height = 0;
};

// Reads `region` (framebuffer pixels, origin bottom-left) of the bound framebuffer and writes it to path, or to
// timestamped_png_name() in the current folder when path is empty, with the text chunks (the picture's material:
// app/material/picture_metadata.h). Throws std::runtime_error naming the path if it cannot be written.
SavedScreenshot save_screenshot(const Viewport& region, const std::string& path, const std::vector<PngText>& texts);

// How a previewer picture was drawn, for its metadata beside its material (app/material/picture_metadata.h): the
// view, the light, the exposure, the lobes' scale, the environment, and in the A/B comparison (`comparing`) the
// pinned material, as a material file, and the split.
nlohmann::ordered_json drawing_settings(const PreviewState& state, bool comparing);

}  // namespace skinlayer
