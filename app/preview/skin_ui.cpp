#include "app/preview/skin_ui.h"

#include <imgui.h>

#include <string>

#include "app/preview/slider_row.h"
#include "core/skin/skin_parameters.h"

namespace skinlayer {
namespace {

const ImVec4 kDimColor{0.7f, 0.7f, 0.7f, 1.0f};

// The six sliders, from core's table of the skin parameters; the fractions whose small values matter most (melanin
// from 0.5% to 50%, blood from 0.2% to 20%) travel logarithmically.
bool skin_sliders(SkinParameters& skin) {
  bool changed = false;
  for (const ParameterInfo& info : skin_parameter_table()) {
    SliderSpec spec{
        std::string(info.flag), std::string(info.description), info.min, info.max, info.default_value, "%.4f"};
    spec.logarithmic = info.flag == "melanin" || info.flag == "blood";
    changed |= slider_row(spec, skin_parameter(skin, info.flag));
  }
  return changed;
}

// "Match colour...": a popup with the colour picker and its Match button. Returns the picked colour when pressed.
std::optional<std::array<double, 3>> match_picker(bool skin, std::array<float, 3>& picked,
                                                  const SkinSectionInput& input) {
  std::optional<std::array<double, 3>> pressed;
  ImGui::BeginDisabled(input.matching);
  if (ImGui::Button(input.matching ? "Matching..." : "Match colour...")) ImGui::OpenPopup("match colour");
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip(skin ? "Pick the colour of the sphere's centre under a white furnace (sRGB); Match sets\n"
                             "melanin, blood and scattering to give it, as one undo step."
                           : "Pick the colour of the sphere's centre under a white furnace (sRGB); Match sets the\n"
                             "top layer's albedo per channel to give it, as one undo step.");
  }
  if (ImGui::BeginPopup("match colour")) {
    ImGui::ColorPicker3("##picked", picked.data(), ImGuiColorEditFlags_DisplayRGB | ImGuiColorEditFlags_DisplayHex);
    if (ImGui::Button("Match")) {
      pressed = std::array<double, 3>{picked[0], picked[1], picked[2]};
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (!input.outcome.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kDimColor, "%s", input.outcome.c_str());
    ImGui::PopTextWrapPos();
  }
  return pressed;
}

}  // namespace

SkinSectionResult skin_section(ColorMaterial& material, std::array<float, 3>& picked, const SkinSectionInput& input) {
  SkinSectionResult result;
  if (material.skin) {
    result.changed = skin_sliders(*material.skin);
    if (ImGui::Button("Use layers instead")) {
      material.skin.reset();  // the layers kept under it: those it had before it became a skin, or the defaults
      result.changed = true;
    }
  } else {
    ImGui::TextColored(kDimColor, "the material is layered: its layers' parameters are set above");
    if (ImGui::Button("Make it a skin")) {
      material.skin = SkinParameters{};
      material.model = SubsurfaceModel::Stam;  // a skin is a stack: the comparison models describe one layer
      result.changed = true;
    }
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip(
          "A two-layer skin from its chromophores (an epidermis over a semi-infinite dermis), solved\n"
          "at 400-700 nm and shown as its linear sRGB under D65, under the same top interface.");
    }
  }
  result.match_srgb = match_picker(material.skin.has_value(), picked, input);
  return result;
}

}  // namespace skinlayer
