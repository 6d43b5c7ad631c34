// One row of the previewer's controls (the layout params_ui.h describes): a label with its tooltip, a slider with
// reset, and a typed-entry box; and a combo in the same layout. ImGui must be inside a frame and a window.
#pragma once

#include <string>
#include <string_view>

namespace skinlayer {

// One slider row's description: what parameter_table() gives for a material parameter.
struct SliderSpec {
  std::string label;
  std::string meaning;
  double min = 0.0;
  double max = 1.0;
  double default_value = 0.0;
  const char* format = "%.3f";
  bool logarithmic = false;  // the slider's travel is logarithmic (for ranges where small values matter most)
};

// The row of a material parameter (core's parameter_table()); unicode: labelled with its symbol.
SliderSpec spec_from_table(std::string_view flag, bool unicode);

// The label column's width: it fits "exposure" (the longest label) in the panel's font.
float label_column();
// The row's label, whose tooltip gives the meaning, the range and the default.
void label_with_tooltip(const SliderSpec& spec);

// A labelled slider with reset and typed entry (see params_ui.h). Returns true when the value changed.
bool slider_row(const SliderSpec& spec, double& value);

// A labelled combo of the row layout; returns true when the choice changed.
bool combo_row(const char* label, int& index, const char* const* items, int count);

}  // namespace skinlayer
