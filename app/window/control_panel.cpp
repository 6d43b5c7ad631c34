#include "app/window/control_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <array>
#include <string>

#include "app/preview/params_ui.h"
#include "app/preview/skin_ui.h"
#include "core/conventions.h"

namespace skinlayer {
namespace {

const ImVec4 kErrorColor{1.0f, 0.45f, 0.4f, 1.0f};
const ImVec4 kBusyColor{1.0f, 0.85f, 0.4f, 1.0f};
const ImVec4 kDimColor{0.7f, 0.7f, 0.7f, 1.0f};

// Directional reflectance (of which surface), transmittance and absorptance per channel, from ColorTables::albedo.
void energy_readout(const SolveResult& shown, bool unicode) {
  const ColorTables& tables = shown.tables();
  ImGui::TextColored(
      kDimColor,
      unicode ? "fractions of the incident flux at θi = %.1f°" : "fractions of the incident flux at theta_i = %.1f deg",
      radians_to_degrees(tables.albedo_theta_i));
  constexpr ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV;
  if (!ImGui::BeginTable("energy", 4, flags)) return;
  ImGui::TableSetupColumn("");
  ImGui::TableSetupColumn("R");
  ImGui::TableSetupColumn("G");
  ImGui::TableSetupColumn("B");
  ImGui::TableHeadersRow();
  struct Row {
    const char* name;
    double (*value)(const DirectionalAlbedo&);
  };
  constexpr std::array kRows = {
      Row{"reflectance", [](const DirectionalAlbedo& a) { return a.reflectance(); }},
      Row{"  surface", [](const DirectionalAlbedo& a) { return a.reflectance_surface; }},
      Row{"  subsurface", [](const DirectionalAlbedo& a) { return a.reflectance_subsurface; }},
      Row{"transmittance", [](const DirectionalAlbedo& a) { return a.transmittance; }},
      Row{"absorptance", [](const DirectionalAlbedo& a) { return a.absorptance; }},
  };
  for (const Row& row : kRows) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(row.name);
    for (int c = 0; c < 3; ++c) {
      ImGui::TableSetColumnIndex(c + 1);
      ImGui::Text("%.4f", row.value(tables.albedo[c]));
    }
  }
  ImGui::EndTable();
}

// Pin as B (the shown material), or with B pinned: Unpin B and the split line's place.
void ab_controls(ComparisonState& comparison, const PanelStatus& status, PanelActions& actions) {
  if (!comparison.pinned) {
    // B is always a full solve: while a preview (capped resolution) is on screen, the button waits for it.
    const bool preview = status.shown != nullptr && status.shown->preview;
    ImGui::BeginDisabled(status.shown == nullptr || preview);
    actions.pin = ImGui::Button("Pin as B");
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      ImGui::SetTooltip(
          preview ? "A preview is on screen: B waits for the full solve."
                  : "Keep the shown material as B and go on editing A: the sphere shows A left of a split line\n"
                    "(drag it) and B right of it, under the same light; the lobes draw B as an outline.");
    }
    // The fitted shaders as B: what an artist's renderer would show of this material, beside it.
    ImGui::BeginDisabled(status.shown == nullptr || preview || status.fitting);
    const char* tooltip =
        "Fit %s to the shown material (as skinlayer fit --target %s) and pin the fit as B:\nthe split sphere and "
        "the lobes show what the fit keeps and loses. A second or two.";
    ImGui::SameLine();
    if (ImGui::Button("B: Principled fit")) actions.pin_fit = ShaderTarget::Principled;
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      ImGui::SetTooltip(tooltip, "the Principled BSDF of Blender 4.2-5.x", "principled");
    }
    ImGui::SameLine();
    if (ImGui::Button("B: OpenPBR fit")) actions.pin_fit = ShaderTarget::OpenPbr;
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      ImGui::SetTooltip(tooltip, "OpenPBR Surface", "openpbr");
    }
    ImGui::EndDisabled();
    if (!status.fit.empty()) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored(kDimColor, "%s", status.fit.c_str());
      ImGui::PopTextWrapPos();
    }
    return;
  }
  actions.unpin = ImGui::Button("Unpin B");
  ImGui::SameLine();
  float split = static_cast<float>(comparison.split);
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderFloat("##split", &split, 0.0f, 1.0f, "split %.2f")) comparison.split = split;
  if (comparison.label != "B (pinned)" && !status.fit.empty()) {  // B is a fit: what it loses, in numbers
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kDimColor, "%s", status.fit.c_str());
    ImGui::PopTextWrapPos();
  }
}

// A button that is disabled while `busy`, with its tooltip shown either way. True when pressed.
bool export_button(const char* label, bool busy, const char* tooltip) {
  ImGui::BeginDisabled(busy);
  const bool pressed = ImGui::Button(label);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", tooltip);
  return pressed;
}

// Target and path on one line, then the Save and Export buttons with the last export's outcome (or the running
// export's progress) beside them.
bool screenshot_controls(ExportOptions& options, const PanelStatus& status, PanelActions& actions) {
  constexpr std::array<const char*, 3> kTargets = {"window", "sphere", "plots"};
  int target = static_cast<int>(options.target);
  ImGui::SetNextItemWidth(ImGui::CalcTextSize("window").x * 2.2f);
  if (ImGui::Combo("##target", &target, kTargets.data(), static_cast<int>(kTargets.size()))) {
    options.target = static_cast<ExportTarget>(target);
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputTextWithHint("##path", "path.png (empty: timestamped name)", &options.path);
  const bool save = ImGui::Button("Save PNG (S)");
  ImGui::SameLine();
  const bool busy = !status.export_progress.empty() || status.shown == nullptr;
  actions.export_bsdf =
      export_button("Export BSDF", busy,
                    "The shown material's whole BSDF (light from above and below, reflection and "
                    "transmission, RGB)\nas a tabulated Fourier BSDF for pbrt-v3's \"fourier\" material and "
                    "layerlab, 1-3 MB;\nto the path above with .bsdf (empty: timestamped).");
  ImGui::SameLine();
  actions.export_merl =
      export_button("Export MERL", busy,
                    "The shown material's reflection (surface + subsurface, RGB) as a MERL BRDF table, 35 "
                    "MB,\nfor BRDF viewers and fitting tools; to the path above with .binary (empty: "
                    "timestamped).");
  ImGui::SameLine();
  actions.export_rgl =
      export_button("Export for pbrt-v4 / Mitsuba 3", busy,
                    "The shown material's reflection (surface + subsurface) as an RGL measured-BSDF tensor "
                    "file,\nspectral, for pbrt-v4's and Mitsuba 3's \"measured\" material (9 MB, a skin 34 "
                    "MB;\nno transmission: Export BSDF keeps it); to the path above with .rgl.bsdf (empty: "
                    "timestamped).");
  actions.export_blender = export_button("Export Blender", busy,
                                         "The shown material as the Principled BSDF of Blender 4.2-5.x, fitted "
                                         "(skinlayer fit --target principled):\na Python script for blender -b "
                                         "--python-exit-code 1 --python FILE.py with a preview scene; to the path "
                                         "above with .py (empty: timestamped).");
  ImGui::SameLine();
  actions.export_mtlx = export_button("Export MaterialX", busy,
                                      "The shown material as OpenPBR Surface, fitted (skinlayer fit --target "
                                      "openpbr),\nin a MaterialX 1.39 document for Maya, Arnold, 3ds Max, Houdini "
                                      "and Unreal;\nto the path above with .mtlx (empty: timestamped).");
  const std::string& line = status.export_progress.empty() ? status.last_export : status.export_progress;
  if (!line.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kDimColor, "%s", line.c_str());
    ImGui::PopTextWrapPos();
  }
  return save;
}

// The header's status: "solving…" while newer parameters are in flight ("refining…" while a preview is shown and
// its full solve runs), and the last result's solve time.
void status_line(const PanelStatus& status) {
  const bool refining = status.shown != nullptr && status.shown->preview;
  if (status.solving) {
    const char* what =
        refining ? (status.unicode ? "refining…" : "refining...") : (status.unicode ? "solving…" : "solving...");
    ImGui::TextColored(kBusyColor, "%s", what);
    ImGui::SameLine();
  }
  if (status.shown != nullptr) {
    ImGui::TextColored(kDimColor, refining ? "preview %.0f ms" : "last solve %.0f ms", 1000.0 * status.shown->seconds);
  } else if (!status.solving) {
    ImGui::TextColored(kDimColor, "no result yet");
  }
  if (status.environment_samples > 0) {  // the environment's estimate (app/render/environment_preview.h)
    ImGui::SameLine();
    ImGui::TextColored(kDimColor, "| %d spp", status.environment_samples);
  }
}

}  // namespace

PanelActions control_panel(const Rect& rect, PreviewState& state, const PanelStatus& status,
                           const FileSectionInput& file) {
  PanelActions actions;
  ImGui::SetNextWindowPos(ImVec2(rect.x, rect.y));
  ImGui::SetNextWindowSize(ImVec2(rect.width, rect.height));
  constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                     ImGuiWindowFlags_NoCollapse;
  ImGui::Begin("##controls", nullptr, flags);

  ImGui::TextUnformatted("skinlayer");
  ImGui::SameLine();
  status_line(status);
  ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - ImGui::CalcTextSize("Help (F1)").x -
                  2.0f * ImGui::GetStyle().FramePadding.x);
  if (ImGui::SmallButton("Help (F1)")) state.show_help = !state.show_help;
  if (!status.error.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kErrorColor, "not solved: %s", status.error.c_str());
    ImGui::PopTextWrapPos();
  }

  if (ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) actions.file = file_section(file);
  if (ImGui::CollapsingHeader("Material", ImGuiTreeNodeFlags_DefaultOpen)) {
    material_controls(state.material, status.unicode);
    actions.reset_material = ImGui::Button("Reset to the paper's default (R)");
  }
  if (ImGui::CollapsingHeader("Skin", ImGuiTreeNodeFlags_DefaultOpen)) {
    const SkinSectionResult skin =
        skin_section(state.material, state.match_color, SkinSectionInput{status.matching, status.match_outcome});
    actions.match_srgb = skin.match_srgb;
  }
  if (ImGui::CollapsingHeader("Light and view", ImGuiTreeNodeFlags_DefaultOpen)) {
    light_controls(state.light, status.unicode);
    view_controls(state.view);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", status.spread.c_str());
    ImGui::PopTextWrapPos();
    ab_controls(state.comparison, status, actions);
  }
  if (ImGui::CollapsingHeader("Lighting", ImGuiTreeNodeFlags_DefaultOpen)) {
    lighting_controls(state.lighting, status.environment_samples);
    if (!status.environment_error.empty()) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored(kErrorColor, "%s", status.environment_error.c_str());
      ImGui::PopTextWrapPos();
    }
  }
  if (ImGui::CollapsingHeader("Energy", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (status.shown != nullptr) {
      energy_readout(*status.shown, status.unicode);
    } else {
      ImGui::TextColored(kDimColor, "waiting for the first solve");
    }
  }
  if (ImGui::CollapsingHeader("Screenshot", ImGuiTreeNodeFlags_DefaultOpen)) {
    actions.save_screenshot = screenshot_controls(state.export_options, status, actions);
  }
  ImGui::End();
  return actions;
}

}  // namespace skinlayer
