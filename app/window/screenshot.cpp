#include "app/window/screenshot.h"

#include "app/render/png_export.h"
#include "app/render/render_target.h"

namespace skinlayer {

SavedScreenshot save_screenshot(const Viewport& region, const std::string& path, const std::vector<PngText>& texts) {
  const std::string target = path.empty() ? timestamped_png_name() : path;
  const Image image{region.width, region.height, read_bound_rgba8(region.x, region.y, region.width, region.height)};
  write_png(image, target, texts);
  return {target, region.width, region.height};
}

}  // namespace skinlayer
