#include "app/preview/scripted_edit.h"

#include <stdexcept>

#include "app/preview/layer_stack.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer {

bool apply_scripted_edit(PreviewState& state, std::string_view verb_view, std::string_view argument_view) {
  const std::string verb(verb_view), argument(argument_view);
  if (verb == "layer") {
    // The layers panel's buttons: "layer add", "layer remove I", "layer up I", "layer down I" (I 1-based).
    const std::size_t gap = argument.find(' ');
    const std::string what = argument.substr(0, gap);
    const std::size_t index = gap == std::string::npos ? 0 : std::stoul(argument.substr(gap + 1)) - 1;
    if (what == "add") {
      add_layer(state.material);
    } else if (what == "remove") {
      remove_layer(state.material, index);
    } else if (what == "up" || what == "down") {
      move_layer(state.material, index, what == "up" ? -1 : +1);
    } else {
      throw std::runtime_error("test action: unknown layer action '" + what + "'");
    }
  } else if (verb == "skin") {  // the Skin section's buttons: "skin on" (Make it a skin), "skin off"
    if (argument == "on") {
      state.material.skin = SkinParameters{};
      state.material.model = SubsurfaceModel::Stam;
    } else {
      state.material.skin.reset();
    }
  } else if (verb == "split") {
    state.comparison.split = std::stod(argument);
  } else if (verb == "lighting") {  // lighting KEY VALUE, KEY one of the lighting flags
    const std::size_t gap = argument.find(' ');
    const std::string key = argument.substr(0, gap), value = argument.substr(gap + 1);
    LightingState& lighting = state.lighting;
    if (key == "env") {
      lighting.environment = value == "none" ? "" : value;
    } else if (key == "env-rotate") {
      lighting.rotate_degrees = std::stod(value);
    } else if (key == "env-ev") {
      lighting.ev = std::stod(value);
    } else if (key == "light") {
      lighting.directional = value == "on";
    } else {
      throw std::runtime_error("test action: unknown lighting key " + key);
    }
  } else if (verb == "set") {
    const std::size_t gap = argument.find(' ');
    const std::string name = argument.substr(0, gap);
    const double value = std::stod(argument.substr(gap + 1));
    Material& layer = state.material.layer;
    if (state.material.skin && name != "sigma" && name != "eta") {  // a skin slider, by its key
      skin_parameter(*state.material.skin, name) = value;
    } else if (name == "sigma") {
      layer.sigma = value;
    } else if (name == "eta") {
      layer.eta = value;
    } else if (name == "g") {
      layer.g = value;
    } else if (name == "T") {
      layer.tau = optical_depth_from_transparency(value);
    } else if (name == "albedo") {
      state.material.albedo_rgb = {value, value, value};
    } else {
      throw std::runtime_error("test action: unknown parameter " + name);
    }
  } else {
    return false;
  }
  return true;
}

}  // namespace skinlayer
