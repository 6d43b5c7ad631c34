#include "app/preview/scripted_edit.h"

#include <stdexcept>

#include "app/cli/flag_parser.h"
#include "app/preview/layer_stack.h"
#include "app/text/numbers.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer {
namespace {

// A number of a test action, or one line naming it ("test action: split = 'x' is not a number").
double number_argument(std::string_view what, std::string_view text) {
  if (const std::optional<double> value = text::parse_number(text)) return *value;
  throw std::runtime_error("test action: " + std::string(what) + " = '" + std::string(text) + "' " +
                           text::number_rejection(text));
}

}  // namespace

bool apply_scripted_edit(PreviewState& state, std::string_view verb_view, std::string_view argument_view) {
  const std::string verb(verb_view), argument(argument_view);
  if (verb == "layer") {
    // The layers panel's buttons: "layer add", "layer remove I", "layer up I", "layer down I" (I 1-based).
    const std::size_t gap = argument.find(' ');
    const std::string what = argument.substr(0, gap);
    // I 1-based; 0 and past the last layer name none (the buttons then do nothing).
    const double place = gap == std::string::npos ? 0.0 : number_argument("layer", argument.substr(gap + 1));
    const std::size_t index = place >= 1.0 && place < 1e6 ? static_cast<std::size_t>(place) - 1 : 1000000;
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
    state.comparison.split = number_argument("split", argument);
  } else if (verb == "lighting") {  // lighting KEY VALUE, KEY one of the lighting flags
    const std::size_t gap = argument.find(' ');
    const std::string key = argument.substr(0, gap), value = argument.substr(gap + 1);
    LightingState& lighting = state.lighting;
    if (key == "env") {
      lighting.environment = value == "none" ? "" : value;
    } else if (key == "env-rotate") {
      lighting.rotate_degrees = number_argument(key, value);
    } else if (key == "env-ev") {
      lighting.ev = number_argument(key, value);
    } else if (key == "light") {
      lighting.directional = value == "on";
    } else {
      throw std::runtime_error("test action: unknown lighting key " + key);
    }
  } else if (verb == "view") {  // view KEY VALUE: the light's sliders, the sphere's radius and translucency
    const std::size_t gap = argument.find(' ');
    const std::string key = argument.substr(0, gap), value = gap == std::string::npos ? "" : argument.substr(gap + 1);
    if (key == "light-theta") {
      state.light.theta_degrees = number_argument(key, value);
    } else if (key == "light-phi") {
      state.light.phi_degrees = number_argument(key, value);
    } else if (key == "radius") {
      state.view.sphere_radius_mm = number_argument(key, value);
    } else if (key == "translucency") {
      state.view.translucency = value == "on";
    } else {
      throw std::runtime_error("test action: unknown view key " + key);
    }
  } else if (verb == "set") {
    const std::size_t gap = argument.find(' ');
    const std::string name = argument.substr(0, gap);
    const double value = number_argument(name, gap == std::string::npos ? "" : argument.substr(gap + 1));
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

std::vector<std::string> drag_steps(std::string_view argument) {
  const std::size_t gap = argument.find(' ');
  const std::string_view name = argument.substr(0, gap);
  std::vector<std::string> steps;
  if (gap == std::string_view::npos) throw std::runtime_error("test action: drag needs NAME V1,V2,...");
  for (const std::string_view value : cli::split_list(argument.substr(gap + 1), ',')) {
    number_argument(name, value);
    steps.push_back(std::string(name) + " " + std::string(value));
  }
  return steps;
}

}  // namespace skinlayer
