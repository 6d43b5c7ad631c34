#include "app/preview/params_ui.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "app/preview/layer_stack.h"
#include "app/preview/slider_row.h"
#include "core/conventions.h"
#include "core/material.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

bool bottom_controls(Material& layer, bool unicode) {
  bool changed = false;
  constexpr std::array<const char*, 3> kKinds = {"air (rough interface)", "matched (no interface)",
                                                 "lambert (diffuse base)"};
  int kind = static_cast<int>(layer.bottom.kind);
  if (combo_row("bottom", kind, kKinds.data(), static_cast<int>(kKinds.size()))) {
    const double lambert = layer.bottom.lambert_albedo;
    layer.bottom = Bottom{};
    layer.bottom.kind = static_cast<BottomKind>(kind);
    layer.bottom.lambert_albedo = kind == static_cast<int>(BottomKind::Lambert) && lambert == 0.0
                                      ? parameter_info("lambert").default_value
                                      : lambert;
    changed = true;
  }
  if (layer.bottom.kind == BottomKind::Lambert) {
    changed |= slider_row(spec_from_table("lambert", unicode), layer.bottom.lambert_albedo);
  }
  if (layer.bottom.kind == BottomKind::Air) {
    bool same = !layer.bottom.sigma && !layer.bottom.eta;
    if (ImGui::Checkbox("bottom interface = top interface", &same)) {
      layer.bottom.sigma = same ? std::nullopt : std::optional<double>(layer.sigma);
      layer.bottom.eta = same ? std::nullopt : std::optional<double>(layer.eta);
      changed = true;
    }
    if (!same) {
      double sigma = layer.bottom_sigma();
      double eta = layer.bottom_eta();
      SliderSpec sigma_spec = spec_from_table("bottom-sigma", unicode);
      SliderSpec eta_spec = spec_from_table("bottom-eta", unicode);
      sigma_spec.default_value = layer.sigma;  // the default is the top's value
      eta_spec.default_value = layer.eta;
      if (slider_row(sigma_spec, sigma)) layer.bottom.sigma = sigma, changed = true;
      if (slider_row(eta_spec, eta)) layer.bottom.eta = eta, changed = true;
    }
  }
  return changed;
}

// The subsurface model of the sphere and plots (the surface term is shared); the compare view shows all three.
bool model_controls(SubsurfaceModel& model) {
  constexpr std::array<const char*, 3> kModels = {"layer (Stam 2001)", "Lambert (same albedo at normal)",
                                                  "Hanrahan-Krueger (single scattering)"};
  int index = static_cast<int>(model);
  if (!combo_row("model", index, kModels.data(), static_cast<int>(kModels.size()))) return false;
  model = static_cast<SubsurfaceModel>(index);
  return true;
}

bool albedo_controls(std::array<double, 3>& albedo_rgb, bool unicode) {
  const ParameterInfo& info = parameter_info("albedo");
  label_with_tooltip(SliderSpec{std::string(unicode ? info.symbol : info.flag),
                                std::string(info.description) + ", per color channel (red, green, blue)", info.min,
                                info.max, info.default_value, "%.3f"});
  ImGui::SameLine(label_column());
  ImGui::SetNextItemWidth(-1.0f);
  std::array<float, 3> color = {static_cast<float>(albedo_rgb[0]), static_cast<float>(albedo_rgb[1]),
                                static_cast<float>(albedo_rgb[2])};
  bool changed = false;
  if (ImGui::ColorEdit3("##albedo", color.data(), ImGuiColorEditFlags_Float | ImGuiColorEditFlags_NoOptions)) {
    for (int c = 0; c < 3; ++c) albedo_rgb[c] = std::clamp(static_cast<double>(color[c]), info.min, info.max);
    changed = true;
  }
  if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) {
    albedo_rgb = {info.default_value, info.default_value, info.default_value};
    changed = true;
  }
  return changed;
}

// What the rough interfaces keep of the light meeting their microsurface more than once: all of it (multiple, the
// default), or nothing, as in Stam 2001 (single).
bool microfacet_controls(Material& layer) {
  constexpr std::array<const char*, 2> kModels = {"multiple (keeps all light)", "single (Stam 2001)"};
  int model = layer.microfacet == MicrofacetModel::Multiple ? 0 : 1;
  const bool changed = combo_row("microfacet", model, kModels.data(), static_cast<int>(kModels.size()));
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "multiple: light that one microfacet sends into another goes on (Heitz et al. 2016); no interface\n"
        "absorbs, and a white layer is white. single: the paper's model, which loses that light.");
  }
  if (changed) layer.microfacet = model == 0 ? MicrofacetModel::Multiple : MicrofacetModel::Single;
  return changed;
}

bool ordinates_controls(Material& layer, bool unicode) {
  const ParameterInfo& info = parameter_info("ordinates");
  bool automatic = !layer.ordinates.has_value();
  bool changed = false;
  if (ImGui::Checkbox("automatic ordinates", &automatic)) {
    layer.ordinates = automatic ? std::nullopt : std::optional<int>(choose_resolution(layer).ordinates);
    changed = true;
  }
  if (!automatic) {
    Material automatic_layer = layer;
    automatic_layer.ordinates.reset();
    double n = *layer.ordinates;
    const SliderSpec spec{std::string(unicode ? info.symbol : info.flag),
                          std::string(info.description) + "; below the material's minimum the solve is refused",
                          info.min,
                          info.max,
                          static_cast<double>(choose_resolution(automatic_layer).ordinates),
                          "%.0f"};
    if (slider_row(spec, n)) {
      layer.ordinates = static_cast<int>(std::lround(n));
      changed = true;
    }
  }
  return changed;
}

// T and tau are one parameter: the slider edits T, the tau box takes an optical depth (inf = semi-infinite).
bool depth_controls(double& tau_value, bool unicode) {
  bool changed = false;
  double transparency = std::exp(-tau_value);
  if (slider_row(spec_from_table("T", unicode), transparency)) {
    tau_value = optical_depth_from_transparency(transparency);
    changed = true;
  }
  const ParameterInfo& info = parameter_info("tau");
  ImGui::PushID("tau");
  label_with_tooltip(SliderSpec{std::string(unicode ? info.symbol : info.flag),
                                std::string(info.description) + " (the same parameter as T = exp(-tau))", info.min,
                                info.max, info.default_value, "%.6g"});
  ImGui::SameLine(label_column());
  ImGui::SetNextItemWidth(-1.0f);
  double tau = tau_value;
  if (ImGui::InputDouble("##typed", &tau, 0.0, 0.0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue) && !std::isnan(tau)) {
    tau_value = std::max(tau, 0.0);
    changed = true;
  }
  if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) {
    tau_value = info.default_value;
    changed = true;
  }
  ImGui::PopID();
  return changed;
}

// One layer's medium: depth, albedo (RGB) and g.
bool medium_controls(EditableLayer& layer, bool unicode) {
  bool changed = depth_controls(layer.layer.tau, unicode);
  changed |= albedo_controls(layer.albedo, unicode);
  changed |= slider_row(spec_from_table("g", unicode), layer.layer.g);
  return changed;
}

// The rough interface above a stacked layer: a checkbox, then its sigma and eta (n_this / n_above).
bool interface_controls(EditableLayer& layer, bool unicode) {
  bool rough = layer.layer.interface.has_value();
  bool changed = false;
  if (ImGui::Checkbox("rough interface above", &rough)) {
    layer.layer.interface = rough ? std::optional<LayerInterface>(LayerInterface{0.3, 1.2}) : std::nullopt;
    changed = true;
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "A rough dielectric interface between this layer and the one above (Beckmann sigma,\n"
        "relative index eta = n_this / n_above); without it the two have the same index.");
  }
  if (layer.layer.interface) {
    SliderSpec sigma = spec_from_table("sigma", unicode);
    sigma.meaning = "Beckmann RMS slope of the interface above this layer";
    sigma.default_value = 0.3;
    const ParameterInfo& eta_info = interface_eta_info();
    const SliderSpec eta{std::string(unicode ? eta_info.symbol : eta_info.flag),
                         std::string(eta_info.description),
                         eta_info.min,
                         eta_info.max,
                         1.2,
                         "%.3f"};
    changed |= slider_row(sigma, layer.layer.interface->sigma);
    changed |= slider_row(eta, layer.layer.interface->eta);
  }
  return changed;
}

// The layers panel: one layer shows its rows as always; a stack shows each layer under a header with its move and
// remove buttons (app/preview/layer_stack.h keeps every edit a valid stack).
bool layers_controls(ColorMaterial& material, bool unicode) {
  std::vector<EditableLayer> layers = editable_layers(material);
  bool edited = false;
  if (layers.size() == 1) {
    edited = medium_controls(layers.front(), unicode);
  } else {
    for (std::size_t i = 0; i < layers.size(); ++i) {
      ImGui::PushID(static_cast<int>(i));
      ImGui::Separator();
      ImGui::AlignTextToFramePadding();
      ImGui::Text("layer %zu%s", i + 1, i == 0 ? " (top)" : i + 1 == layers.size() ? " (bottom)" : "");
      ImGui::SameLine();
      bool structural = false;
      const auto button = [&](const char* label, bool enabled, const char* tip, const auto& action) {
        ImGui::SameLine();
        ImGui::BeginDisabled(!enabled);
        if (ImGui::SmallButton(label)) {
          action();
          structural = true;
        }
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", tip);
      };
      button("up", can_move(material, i, -1), "move this layer up (its interface above moves with it)",
             [&] { move_layer(material, i, -1); });
      button("down", can_move(material, i, +1), "move this layer down (only the last may be semi-infinite)",
             [&] { move_layer(material, i, +1); });
      button("remove", true, "remove this layer", [&] { remove_layer(material, i); });
      if (structural) {
        ImGui::PopID();
        return true;  // the list changed: the rows are drawn from it next frame
      }
      if (i > 0) edited |= interface_controls(layers[i], unicode);
      edited |= medium_controls(layers[i], unicode);
      ImGui::PopID();
    }
    ImGui::Separator();
  }
  if (edited) set_layers(material, layers);
  if (ImGui::Button("add layer")) {
    add_layer(material);
    return true;
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Add a layer under the last one (a stack: an epidermis over a dermis, a clear coat over a\n"
        "base). The comparison models describe one layer; a stack shows the layer model.");
  }
  return edited;
}

}  // namespace

bool material_controls(ColorMaterial& material, bool unicode) {
  Material& layer = material.layer;
  bool changed = false;
  changed |= slider_row(spec_from_table("sigma", unicode), layer.sigma);
  changed |= slider_row(spec_from_table("eta", unicode), layer.eta);
  changed |= microfacet_controls(layer);
  if (material.skin) {  // its layers come from the chromophores (the Skin section)
    ImGui::TextColored(ImVec4(0.7f, 0.7f, 0.7f, 1.0f), "layers: a skin's, from its chromophores (Skin, below)");
    return changed;
  }
  changed |= layers_controls(material, unicode);
  changed |= bottom_controls(layer, unicode);
  changed |= ordinates_controls(layer, unicode);
  if (material.layer.below.empty()) changed |= model_controls(material.model);
  return changed;
}

bool light_controls(LightState& light, bool unicode) {
  bool changed = false;
  changed |= slider_row(SliderSpec{unicode ? "θ light" : "light theta",
                                   "light angle from the view direction, degrees (also: drag on the sphere)", 0.0,
                                   kMaxLightThetaDegrees, LightState{}.theta_degrees, "%.1f°"},
                        light.theta_degrees);
  changed |= slider_row(
      SliderSpec{unicode ? "φ light" : "light phi", "light azimuth in the picture plane, degrees; 180 = from the left",
                 -180.0, 180.0, LightState{}.phi_degrees, "%.1f°"},
      light.phi_degrees);
  return changed;
}

bool view_controls(ViewOptions& view) {
  bool changed = false;
  {  // the lobe plots may show another model than the sphere
    constexpr std::array<const char*, 4> kPlotModels = {"same as the sphere", "layer (Stam 2001)", "Lambert",
                                                        "Hanrahan-Krueger"};
    int index = view.plot_model ? static_cast<int>(*view.plot_model) + 1 : 0;
    if (combo_row("plots", index, kPlotModels.data(), static_cast<int>(kPlotModels.size()))) {
      view.plot_model = index == 0 ? std::nullopt : std::optional(static_cast<SubsurfaceModel>(index - 1));
      changed = true;
    }
  }
  changed |= slider_row(SliderSpec{"exposure", "tone-map exposure in stops (the radiance is scaled by 2^stops)",
                                   kMinStops, kMaxStops, ViewOptions{}.exposure_stops, "%+.1f EV"},
                        view.exposure_stops);
  changed |=
      slider_row(SliderSpec{"radius",
                            "the sphere's radius in mm: its subsurface light spreads over it by the "
                            "material's profile, past the terminator (a material with lengths)",
                            kMinSphereRadiusMm, kMaxSphereRadiusMm, ViewOptions{}.sphere_radius_mm, "%.1f mm", true},
                 view.sphere_radius_mm);
  changed |= ImGui::Checkbox("translucency", &view.translucency);
  ImGui::SameLine();
  changed |= ImGui::Checkbox("log lobe radius (L)", &view.log_lobes);
  ImGui::SameLine();
  constexpr std::array<const char*, 4> kViews = {"sphere", "plots", "both", "compare: Lambert | HK | layer"};
  int kind = static_cast<int>(view.view);
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::Combo("##view", &kind, kViews.data(), static_cast<int>(kViews.size()))) {
    view.view = static_cast<ViewKind>(kind);
    changed = true;
  }
  return changed;
}

bool lighting_controls(LightingState& lighting, int samples) {
  bool changed = false;
  constexpr std::array<const char*, 5> kSources = {"none", "furnace", "studio", "sky", "file (.hdr)"};
  int source = 0;
  for (int k = 1; k < 4; ++k) {
    if (lighting.environment == kSources[k]) source = k;
  }
  if (source == 0 && !lighting.environment.empty()) source = 4;
  const int before = source;
  if (combo_row("env", source, kSources.data(), static_cast<int>(kSources.size())) && source != before) {
    if (source == 0) lighting.environment.clear();
    if (source >= 1 && source <= 3) lighting.environment = kSources[source];
    if (source == 4 && !lighting.typed_path.empty()) lighting.environment = lighting.typed_path;
    changed = true;
  }
  // The .hdr file: a typed path, opened by Load (or by choosing "file" above).
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Load .hdr").x -
                          3.0f * ImGui::GetStyle().FramePadding.x - ImGui::GetStyle().ItemSpacing.x);
  ImGui::InputTextWithHint("##hdr", "equirectangular .hdr path", &lighting.typed_path);
  ImGui::SameLine();
  if (ImGui::Button("Load .hdr") && !lighting.typed_path.empty()) {
    lighting.environment = lighting.typed_path;
    changed = true;
  }
  if (!lighting.environment.empty()) {  // without an environment the directional light is the only light
    changed |= slider_row(
        SliderSpec{"rotate", "the environment turned about the vertical, degrees", -180.0, 180.0, 0.0, "%.0f°"},
        lighting.rotate_degrees);
    changed |= slider_row(
        SliderSpec{"env EV", "the environment's radiance scaled by 2^EV", kMinStops, kMaxStops, 0.0, "%+.1f EV"},
        lighting.ev);
    constexpr std::array<const char*, 3> kBackgrounds = {"hidden", "shown", "blurred"};
    int background = static_cast<int>(lighting.background);
    if (combo_row("backdrop", background, kBackgrounds.data(), static_cast<int>(kBackgrounds.size()))) {
      lighting.background = static_cast<EnvironmentBackground>(background);
      changed = true;
    }
    changed |= ImGui::Checkbox("directional light too", &lighting.directional);
    ImGui::SameLine();
    ImGui::TextDisabled("%d samples per pixel", samples);
  }
  constexpr std::array<const char*, 3> kToneMaps = {"exponential", "ACES", "none (clamp)"};
  int tone_map = static_cast<int>(lighting.tone_map);
  if (combo_row("tone map", tone_map, kToneMaps.data(), static_cast<int>(kToneMaps.size()))) {
    lighting.tone_map = static_cast<ToneMap>(tone_map);
    changed = true;
  }
  return changed;
}

}  // namespace skinlayer
