#include "app/window/screenshot.h"

#include "app/material/material_json.h"
#include "app/render/png_export.h"
#include "app/render/render_target.h"
#include "app/render/scene.h"

namespace skinlayer {

SavedScreenshot save_screenshot(const Viewport& region, const std::string& path, const std::vector<PngText>& texts) {
  const std::string target = path.empty() ? timestamped_png_name() : path;
  const Image image{region.width, region.height, read_bound_rgba8(region.x, region.y, region.width, region.height)};
  write_png(image, target, texts);
  return {target, region.width, region.height};
}

nlohmann::ordered_json drawing_settings(const PreviewState& state, bool comparing) {
  nlohmann::ordered_json settings = {{"command", "previewer"},
                                     {"view", std::string(view_kind_name(state.view.view))},
                                     {"light_theta", state.light.theta_degrees},
                                     {"light_phi", state.light.phi_degrees},
                                     {"exposure", exposure_multiplier(state.view)},
                                     {"scale", state.view.log_lobes ? "log" : "linear"}};
  if (!state.lighting.environment.empty()) settings["environment"] = state.lighting.environment;
  if (comparing) {  // the A/B comparison's pinned material, as a material file
    settings["pinned"] = material_json(material_document(*state.comparison.pinned));
    settings["pinned_label"] = state.comparison.label;  // a fit's B: the material with eta 1, the fit in its tables
    settings["split"] = state.comparison.split;
  }
  return settings;
}

}  // namespace skinlayer
