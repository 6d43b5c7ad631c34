#include "app/preview/slider_row.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/material.h"

namespace skinlayer {
namespace {

constexpr float kTypedColumn = 0.24f;  // the typed-entry box's fraction of the row

}  // namespace

float label_column() { return ImGui::CalcTextSize("exposure").x + 2.0f * ImGui::GetStyle().ItemSpacing.x; }

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

SliderSpec spec_from_table(std::string_view flag, bool unicode) {
  const ParameterInfo& info = parameter_info(flag);
  return SliderSpec{std::string(unicode ? info.symbol : info.flag),
                    std::string(info.description),
                    info.min,
                    info.max,
                    info.default_value,
                    "%.3f"};
}

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
  const ImGuiSliderFlags flags = ImGuiSliderFlags_NoInput | ImGuiSliderFlags_AlwaysClamp |
                                 (spec.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
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

bool combo_row(const char* label, int& index, const char* const* items, int count) {
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(label);
  ImGui::SameLine(label_column());
  ImGui::SetNextItemWidth(-1.0f);
  return ImGui::Combo((std::string("##") + label).c_str(), &index, items, count);
}

}  // namespace skinlayer
