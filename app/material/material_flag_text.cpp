// app/material/material_flag_text.h: a material as the command line's text.
#include "app/material/material_flag_text.h"

#include <optional>

#include "app/material/exact_transparency.h"
#include "app/text/numbers.h"
#include "core/skin/skin_optics.h"

namespace skinlayer {

std::string format_layer_spec(const StackedLayer& layer, const AlbedoRgb& albedo) {
  // Appended piece by piece: GCC 12 reports a false -Wrestrict overlap for a literal prepended to a temporary.
  const std::optional<double> transparency = exact_transparency(layer.tau);
  std::string text = transparency ? "T=" : "tau=";
  text.append(text::format_shortest(transparency.value_or(layer.tau)));
  text.append(",albedo=").append(text::format_shortest(albedo[0]));
  if (albedo[1] != albedo[0] || albedo[2] != albedo[0]) {
    text.append(":").append(text::format_shortest(albedo[1])).append(":").append(text::format_shortest(albedo[2]));
  }
  text.append(",g=").append(text::format_shortest(layer.g));
  if (layer.extinction) text.append(",mu_t=").append(text::format_shortest(*layer.extinction));
  if (layer.interface) {
    text.append(",sigma=").append(text::format_shortest(layer.interface->sigma));
    text.append(",eta=").append(text::format_shortest(layer.interface->eta));
  }
  return text;
}

std::string format_skin_spec(const SkinParameters& skin) {
  std::string text;
  for (const ParameterInfo& info : skin_parameter_table()) {
    if (!text.empty()) text += ',';
    text.append(info.flag);
    text += '=';
    text += text::format_shortest(skin_parameter(skin, info.flag));
  }
  return text;
}

std::string material_to_flags(const Material& material) {
  std::string text =
      "--sigma " + text::format_shortest(material.sigma) + " --eta " + text::format_shortest(material.eta);
  if (material.below.empty()) {
    // T with the fewest digits that give back the same tau (0.1, not exp(-(-ln 0.1)) = 0.10000000000000002).
    const std::optional<double> transparency = exact_transparency(material.tau);
    const std::string depth =
        transparency ? " --T " + text::format_shortest(*transparency) : " --tau " + text::format_shortest(material.tau);
    text += depth;
    text += " --albedo " + text::format_shortest(material.albedo) + " --g " + text::format_shortest(material.g);
    if (material.extinction) text += " --mu-t " + text::format_shortest(*material.extinction);
  } else {
    for (const StackedLayer& layer : stack_layers(material)) {
      text += " --layer " + format_layer_spec(layer, {layer.albedo, layer.albedo, layer.albedo});
    }
  }
  text += " --bottom " + format_bottom(material.bottom);
  if (material.bottom.sigma) text += " --bottom-sigma " + text::format_shortest(*material.bottom.sigma);
  if (material.bottom.eta) text += " --bottom-eta " + text::format_shortest(*material.bottom.eta);
  if (material.ordinates) text += " --ordinates " + std::to_string(*material.ordinates);
  if (material.microfacet != Material{}.microfacet) {
    text += " --microfacet " + std::string(microfacet_model_name(material.microfacet));
  }
  return text;
}

}  // namespace skinlayer
