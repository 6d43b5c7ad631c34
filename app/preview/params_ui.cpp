#include "app/preview/params_ui.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/conventions.h"
#include "core/material.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

// One slider row's description: what parameter_table() gives for a material parameter.
struct SliderSpec {
  std::string label;
  std::string meaning;
  double min = 0.0;
  double max = 1.0;
  double default_value = 0.0;
  const char* format = "%.3f";
};

SliderSpec spec_from_table(std::string_view flag, bool unicode) {
  const ParameterInfo& info = parameter_info(flag);
  return SliderSpec{std::string(unicode ? info.symbol : info.flag),
                    std::string(info.description),
                    info.min,
                    info.max,
                    info.default_value,
                    "%.3f"};
}

// The label column fits "exposure" (the longest label) in the panel's font; the typed-entry box takes a fixed
// fraction of the row.
float label_column() { return ImGui::CalcTextSize("exposure").x + 2.0f * ImGui::GetStyle().ItemSpacing.x; }
constexpr float kTypedColumn = 0.24f;

void label_with_tooltip(const SliderSpec& spec) {
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(spec.label.c_str());
  if (ImGui::IsItemHovered()) {
    char range[160];
    std::snprintf(range, sizeof range, "range [%g, %g], default %g", spec.min, spec.max, spec.default_value);
    ImGui::SetTooltip("%s\n%s\nCtrl-click or right-click the slider: reset. Box: type a value, Enter.",
                      spec.meaning.c_str(), range);
  }
}

// A labelled slider with reset and typed entry (see params_ui.h). Returns true when the value changed.
bool slider_row(const SliderSpec& spec, double& value) {
  ImGui::PushID(spec.label.c_str());
  const double before = value;
  const float row = ImGui::GetContentRegionAvail().x;
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  label_with_tooltip(spec);
  ImGui::SameLine(label_column());
  ImGui::SetNextItemWidth(row * (1.0f - kTypedColumn) - label_column() - spacing);

  // Ctrl-click starts a "reset" press that holds the default until the mouse is released (the slider would
  // otherwise follow the mouse while the button is held).
  const ImGuiID slider_id = ImGui::GetID("##slider");
  ImGuiStorage* storage = ImGui::GetStateStorage();
  constexpr ImGuiSliderFlags flags = ImGuiSliderFlags_NoInput | ImGuiSliderFlags_AlwaysClamp;
  ImGui::SliderScalar("##slider", ImGuiDataType_Double, &value, &spec.min, &spec.max, spec.format, flags);
  if (ImGui::IsItemActivated() && ImGui::GetIO().KeyCtrl) storage->SetBool(slider_id, true);
  if (storage->GetBool(slider_id, false)) {
    value = spec.default_value;
    if (!ImGui::IsItemActive()) storage->SetBool(slider_id, false);
  }
  if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) value = spec.default_value;

  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  double typed = value;
  if (ImGui::InputDouble("##typed", &typed, 0.0, 0.0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue) &&
      !std::isnan(typed)) {
    value = std::clamp(typed, spec.min, spec.max);
  }
  ImGui::PopID();
  return value != before;
}

bool bottom_controls(Material& layer, bool unicode) {
  bool changed = false;
  constexpr std::array<const char*, 3> kKinds = {"air (rough interface)", "matched (no interface)",
                                                 "lambert (diffuse base)"};
  int kind = static_cast<int>(layer.bottom.kind);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("bottom");
  ImGui::SameLine(label_column());
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::Combo("##bottom", &kind, kKinds.data(), static_cast<int>(kKinds.size()))) {
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
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("model");
  ImGui::SameLine(label_column());
  ImGui::SetNextItemWidth(-1.0f);
  if (!ImGui::Combo("##model", &index, kModels.data(), static_cast<int>(kModels.size()))) return false;
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

}  // namespace

bool material_controls(ColorMaterial& material, bool unicode) {
  Material& layer = material.layer;
  bool changed = false;
  changed |= slider_row(spec_from_table("sigma", unicode), layer.sigma);
  changed |= slider_row(spec_from_table("eta", unicode), layer.eta);

  // T and τb are one parameter: the slider edits T, the τb box takes an optical depth (inf = semi-infinite).
  double transparency = layer.transparency();
  if (slider_row(spec_from_table("T", unicode), transparency)) {
    layer.tau = optical_depth_from_transparency(transparency);
    changed = true;
  }
  {
    const ParameterInfo& info = parameter_info("tau");
    ImGui::PushID("tau");
    label_with_tooltip(SliderSpec{std::string(unicode ? info.symbol : info.flag),
                                  std::string(info.description) + " (the same parameter as T = exp(-tau))", info.min,
                                  info.max, info.default_value, "%.6g"});
    ImGui::SameLine(label_column());
    ImGui::SetNextItemWidth(-1.0f);
    double tau = layer.tau;
    if (ImGui::InputDouble("##typed", &tau, 0.0, 0.0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue) &&
        !std::isnan(tau)) {
      layer.tau = std::max(tau, 0.0);
      changed = true;
    }
    if (ImGui::IsItemClicked(ImGuiMouseButton_Right)) {
      layer.tau = info.default_value;
      changed = true;
    }
    ImGui::PopID();
  }

  changed |= albedo_controls(material.albedo_rgb, unicode);
  changed |= slider_row(spec_from_table("g", unicode), layer.g);
  changed |= bottom_controls(layer, unicode);
  changed |= ordinates_controls(layer, unicode);
  changed |= model_controls(material.model);
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
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("plots");
    ImGui::SameLine(label_column());
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::Combo("##plot-model", &index, kPlotModels.data(), static_cast<int>(kPlotModels.size()))) {
      view.plot_model = index == 0 ? std::nullopt : std::optional(static_cast<SubsurfaceModel>(index - 1));
      changed = true;
    }
  }
  changed |= slider_row(SliderSpec{"exposure", "tone-map exposure in stops (the radiance is scaled by 2^stops)",
                                   kMinStops, kMaxStops, ViewOptions{}.exposure_stops, "%+.1f EV"},
                        view.exposure_stops);
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

}  // namespace skinlayer
