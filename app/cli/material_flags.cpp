#include "app/cli/material_flags.h"

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/layer_flag.h"
#include "app/cli/skin_flag.h"
#include "app/material/exact_transparency.h"
#include "app/material/material_file.h"
#include "app/material/presets.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"

namespace skinlayer::cli {
namespace {

// parameter_table() names the Lambertian base's albedo "lambert"; on the command line it is the A of
// --bottom lambert:A.
constexpr std::string_view kLambertParameter = "lambert";

constexpr std::array<std::string_view, 13> kMaterialFlags = {
    "sigma",  "eta",          "T",          "tau",       "albedo",     "g", "mu-t", "layer",
    "bottom", "bottom-sigma", "bottom-eta", "ordinates", "microfacet",
};
// The single layer's own flags, which --layer replaces.
constexpr std::array<std::string_view, 5> kSingleLayerFlags = {"T", "tau", "albedo", "g", "mu-t"};
constexpr std::array<std::string_view, 2> kSourceFlags = {"material", "preset"};

// The flag's value checked against its row of the parameter table, or nullopt when the flag is absent.
std::optional<double> checked_number(const ParsedFlags& flags, std::string_view name) {
  const std::optional<std::string_view> text = flags.value(name);
  if (!text) return std::nullopt;
  const ParameterInfo& info = parameter_info(name);
  const std::optional<double> value = text::parse_number(*text);
  if (!value) {
    throw UsageError(std::string(name) + " = " + text::quoted(*text) + " " + text::number_rejection(*text) +
                     "; valid range is " + range_text(info) + " (" + std::string(info.description) + ")");
  }
  check_parameter(info, *value);
  return value;
}

std::optional<int> checked_ordinates(const ParsedFlags& flags) {
  const std::optional<double> value = checked_number(flags, "ordinates");
  if (!value) return std::nullopt;
  if (*value != std::floor(*value)) {
    const ParameterInfo& info = parameter_info("ordinates");
    throw UsageError("ordinates = " + text::format_number(*value) + " is not a whole number; valid range is " +
                     range_text(info) + " (" + std::string(info.description) + ")");
  }
  return static_cast<int>(*value);
}

// One help entry: the flag as written, then its meaning, symbol, range and default.
std::string usage_entry(const ParameterInfo& info) {
  const std::string flag(info.flag);
  const std::string meaning = std::string(info.description) + " (" + std::string(info.symbol) + ")";
  const std::string range = "Range " + range_text(info);
  const std::string default_number = text::format_short(info.default_value);
  std::string spelling = "--" + flag + " X";
  std::string body = meaning + ". " + range + "; default " + default_number + ".";
  if (info.flag == kLambertParameter) {
    spelling = "--bottom air|matched|lambert:A";
    body =
        "the layer's bottom; default air.\n"
        "      air: a rough interface to the medium below (see --bottom-sigma, --bottom-eta);\n"
        "      matched: an index-matched half-space below, no interface;\n"
        "      lambert:A: a diffuse base; A = " +
        meaning + ". " + range + ".";
  } else if (info.flag == "T") {
    body += " Not together with --tau.";
  } else if (info.flag == "tau") {
    body = meaning + ". " + range + "; default " + default_number +
           " (T = " + text::format_short(parameter_info("T").default_value) + "). Not together with --T.";
  } else if (info.flag == "bottom-sigma") {
    body = meaning + ". " + range + "; default the top's --sigma. Only with --bottom air.";
  } else if (info.flag == "bottom-eta") {
    body = meaning + ". " + range + "; default the top's --eta. Only with --bottom air.";
  } else if (info.flag == "ordinates") {
    spelling = "--ordinates N";
    body = meaning + ". A whole number. " + range + "; default automatic.";
  } else if (info.flag == "mu-t") {
    body = meaning + ". " + range + "; default none\n      (no physical length: lateral distances in mean free paths).";
  }
  return "  " + spelling + "\n      " + body + "\n";
}

}  // namespace

std::span<const std::string_view> material_flag_names() { return kMaterialFlags; }

std::vector<std::string_view> material_flags_and(std::initializer_list<std::string_view> own_flags) {
  std::vector<std::string_view> flags(kMaterialFlags.begin(), kMaterialFlags.end());
  flags.insert(flags.end(), kSourceFlags.begin(), kSourceFlags.end());
  flags.insert(flags.end(), own_flags);
  return flags;
}

std::array<double, 3> albedo_rgb_from_text(std::string_view text) {
  std::array<double, 3> rgb{};
  const std::vector<std::string_view> parts = split_list(text, ',');
  if (parts.size() != 1 && parts.size() != 3) {
    throw UsageError("albedo = " + text::quoted(text) + " must be one number or three (r,g,b), each in [0, 1]");
  }
  for (std::size_t c = 0; c < 3; ++c) {
    const std::string_view part = parts[parts.size() == 1 ? 0 : c];
    const std::optional<double> value = text::parse_number(part);
    if (!value)
      throw UsageError("albedo = " + text::quoted(text) + ": " + text::quoted(part) + " " +
                       text::number_rejection(part));
    check_parameter(parameter_info("albedo"), *value);
    rgb[c] = *value;
  }
  return rgb;
}

MicrofacetModel microfacet_from_text(std::string_view text) {
  const std::optional<MicrofacetModel> model = parse_microfacet_model(text);
  if (!model) {
    throw UsageError("microfacet = " + text::quoted(text) +
                     " is not a microfacet model; valid values are multiple (energy-conserving, the default) and "
                     "single (Stam 2001)");
  }
  return *model;
}

namespace {

// --T, --tau, --albedo and --g set the one layer of a single-layer material. On a stack from --material or --preset
// they would change its top layer alone (a stack's --albedo 0.5 would still be RGB below), so they are refused
// there, with the stack's own --layer flags to edit instead.
void refuse_single_layer_flags_on_a_stack(const ParsedFlags& flags, const MaterialDocument& document,
                                          const std::string& origin) {
  if (document.layer.below.empty() || flags.has("layer")) return;  // with --layer, the check below speaks
  for (const std::string_view single : kSingleLayerFlags) {
    if (!flags.has(single)) continue;
    std::string layers;
    const std::vector<StackedLayer> stack = stack_layers(document.layer);
    for (std::size_t i = 0; i < stack.size(); ++i) {
      layers += " --layer " + format_layer_spec(stack[i], document.layer_albedo(i));
    }
    throw UsageError(
        "flag --" + std::string(single) + " sets a single layer's value, and the material" + origin +
        " is a stack of " + std::to_string(stack.size()) +
        " layers; give every layer with --layer instead (they replace the stack's), these being its own:" + layers);
  }
}

}  // namespace

MaterialDocument material_document_from_flags(const ParsedFlags& flags, AlbedoFlag albedo_flag) {
  if (flags.has("material") && flags.has("preset")) {
    throw UsageError("flags --material and --preset both name the material; give only one");
  }
  if (flags.has("T") && flags.has("tau")) {
    throw UsageError("flags --T and --tau both set the optical depth; give only one");
  }
  MaterialDocument document;
  std::string origin;  // where the bottom came from, for the error below
  if (const auto path = flags.value("material")) {
    if (path->empty()) throw UsageError("material needs a file name, as in --material skin.json");
    document = read_material_file(std::string(*path));
    origin = " (from " + std::string(*path) + ")";
  } else if (const auto name = flags.value("preset")) {
    document = preset_material(*name);
    origin = " (from preset " + std::string(*name) + ")";
  }
  Material& material = document.layer;
  refuse_single_layer_flags_on_a_stack(flags, document, origin);
  if (const auto value = checked_number(flags, "sigma")) material.sigma = *value;
  if (const auto value = checked_number(flags, "eta")) material.eta = *value;
  if (const auto value = checked_number(flags, "T")) material.tau = optical_depth_from_transparency(*value);
  if (const auto value = checked_number(flags, "tau")) material.tau = *value;
  if (albedo_flag == AlbedoFlag::GreyOrRgb) {
    if (const auto text = flags.value("albedo")) document.albedo_rgb = albedo_rgb_from_text(*text);
  } else {
    const std::optional<std::string_view> text = flags.value("albedo");
    if (text && text->find(',') != std::string_view::npos && text::parse_number(*text) == std::nullopt) {
      throw UsageError("albedo = " + text::quoted(*text) +
                       " is one per colour channel, and this command takes one albedo: a grey material, whose "
                       "spectrum is flat, or a skin (--skin) for a spectrum that is not");
    }
    if (const auto value = checked_number(flags, "albedo")) document.albedo_rgb = {*value, *value, *value};
  }
  material.albedo = document.albedo_rgb[0];
  if (const auto value = checked_number(flags, "g")) material.g = *value;
  if (const auto value = checked_number(flags, "mu-t")) material.extinction = *value;
  const std::vector<std::string_view> layer_specs = flags.values("layer");
  if (!layer_specs.empty()) {
    for (const std::string_view single : kSingleLayerFlags) {
      if (flags.has(single)) {
        throw UsageError("flag --" + std::string(single) +
                         " sets the single layer's value; with --layer give it inside each layer, as in --layer " +
                         "T=0.5,albedo=0.9,g=0.8");
      }
    }
    material.below.clear();
    document.below_rgb.clear();
    for (std::size_t i = 0; i < layer_specs.size(); ++i) {
      const LayerSpec spec =
          parse_layer_spec(layer_specs[i], static_cast<int>(i) + 1, albedo_flag == AlbedoFlag::GreyOrRgb);
      if (i == 0) {
        material.tau = spec.tau;
        material.g = spec.g;
        material.extinction = spec.extinction;
      } else {
        material.below.push_back({spec.tau, spec.albedo[0], spec.g, spec.interface, spec.extinction});
      }
      document.set_layer_albedo(i, spec.albedo);
    }
  }
  if (const auto text = flags.value("bottom")) {
    material.bottom = parse_bottom(*text);
    origin.clear();
  }
  for (const std::string_view bottom_flag : {"bottom-sigma", "bottom-eta"}) {
    if (flags.has(bottom_flag) && material.bottom.kind != BottomKind::Air) {
      throw UsageError("flag --" + std::string(bottom_flag) + " applies only to --bottom air, not --bottom " +
                       format_bottom(material.bottom) + origin);
    }
  }
  if (const auto value = checked_number(flags, "bottom-sigma")) material.bottom.sigma = *value;
  if (const auto value = checked_number(flags, "bottom-eta")) material.bottom.eta = *value;
  if (const std::optional<int> ordinates = checked_ordinates(flags)) material.ordinates = ordinates;
  if (const auto text = flags.value("microfacet")) material.microfacet = microfacet_from_text(*text);
  if (const auto text = flags.value(kSkinFlag)) {
    document.skin = parse_skin_spec(*text, document.skin.value_or(SkinParameters{}));
  }
  if (document.skin) {
    for (const std::string_view layer_flag :
         {"T", "tau", "albedo", "g", "mu-t", "layer", "bottom", "bottom-sigma", "bottom-eta"}) {
      if (flags.has(layer_flag)) {
        throw UsageError("flag --" + std::string(layer_flag) +
                         " sets a layer or the bottom, which a skin makes from the chromophores (an epidermis over a"
                         " semi-infinite dermis); with --skin or a skin material give only --sigma, --eta and"
                         " --ordinates");
      }
    }
  }
  validate(material);
  return document;
}

Material material_from_flags(const ParsedFlags& flags) { return single_channel(material_document_from_flags(flags)); }

Material single_channel(const MaterialDocument& document) {
  if (document.skin) {
    throw UsageError(
        "the material is a spectral skin (--skin) and this command solves one grey material; give"
        " --wavelength NM for one wavelength's");
  }
  if (!document.grey()) {
    throw UsageError("the material's albedo is RGB (" + text::format_shortest(document.albedo_rgb[0]) + ", " +
                     text::format_shortest(document.albedo_rgb[1]) + ", " +
                     text::format_shortest(document.albedo_rgb[2]) +
                     ") and this command solves one channel; give --albedo A");
  }
  return document.layer;
}

std::string rgb_albedo_usage() {
  const ParameterInfo& albedo = parameter_info("albedo");
  return "  --albedo A | r,g,b   single-scattering albedo, grey or per color channel, each in " + range_text(albedo) +
         " (default " + text::format_short(albedo.default_value) + ")\n";
}

std::string material_flags_usage() {
  std::string text =
      "Material flags (--name value or --name=value; an omitted flag takes its default, or the file's):\n"
      "  --material FILE\n"
      "      start from a material file (JSON; see `skinlayer material`), or a PNG or .bsdf that skinlayer\n"
      "      wrote (its material is stored in it); the flags below, given next to it, override its values.\n"
      "  --preset NAME\n"
      "      start from a named preset (`skinlayer presets` lists them); not together with --material.\n";
  for (const ParameterInfo& info : parameter_table()) {
    // --bottom (the table's "lambert" row) is listed before the flags that qualify it.
    if (info.flag == kLambertParameter) continue;
    if (info.flag == "bottom-sigma") text += usage_entry(parameter_info(kLambertParameter));
    text += usage_entry(info);
    if (info.flag == "g") {
      text +=
          "  --layer T=X|tau=X[,albedo=A][,g=G][,mu_t=M][,sigma=S,eta=E]\n"
          "      one layer of a stack, repeated top to bottom, in place of --T/--tau, --albedo, --g and --mu-t.\n"
          "      Keys range as the flags; albedo r:g:b where --albedo takes RGB. sigma and eta (n_this/n_above,\n"
          "      range " +
          range_text(interface_eta_info()) +
          ", 1 = none) give a rough interface above the layer, for every layer but the first (both or\n"
          "      neither). Only the last layer may be semi-infinite (T=0). --bottom applies under the last layer.\n";
    }
  }
  text +=
      "  --microfacet multiple|single\n"
      "      what every rough interface keeps of the light that meets its microsurface; default multiple.\n"
      "      multiple: also the light scattered more than once on the microsurface (Heitz et al. 2016), so\n"
      "      that no interface absorbs; single: one microfacet meeting, the rest lost (Stam 2001's model).\n";
  return text;
}

}  // namespace skinlayer::cli
