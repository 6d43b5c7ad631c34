// The control panel on the left of the window: the material file (file_panel.h), the material, light and view
// controls (params_ui), the energy readout at the light's angle, the screenshot settings, and the status line.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "app/preview/preview_state.h"
#include "app/preview/solve_worker.h"
#include "app/preview/view_layout.h"
#include "app/solution/fitted_tables.h"
#include "app/window/file_panel.h"

namespace skinlayer {

struct PanelStatus {
  const SolveResult* shown = nullptr;  // the result on screen; null before the first one
  bool solving = false;                // newer parameters than the shown ones are in flight
  std::string error;                   // why the newest parameters could not be solved; empty if they could
  std::string last_export;             // the last screenshot's or export's outcome ("saved …" or the error)
  std::string export_progress;         // the running export's progress; empty when none runs
  bool unicode = false;                // the font has Greek letters and symbols
  int environment_samples = 0;         // the environment estimate's samples per pixel so far
  std::string environment_error;       // why the chosen environment could not be loaded
  bool matching = false;               // a "Match colour..." runs (app/window/match_job.h)
  std::string match_outcome;           // the last match's outcome; empty: none
  std::string spread;                  // the translucency's state (app/window/spread_job.h)
  std::string fit;                     // "fitting..." while a fit for B runs, then its summary; empty: none
  bool fitting = false;
};

struct PanelActions {
  bool save_screenshot = false;
  bool export_bsdf = false;  // the Export BSDF button (app/window/export_job.h)
  bool export_merl = false;  // the Export MERL button
  bool export_rgl = false;   // the Export for pbrt-v4 / Mitsuba 3 button
  bool export_blender = false;  // the Export Blender button (a fitted Principled BSDF)
  bool export_mtlx = false;     // the Export MaterialX button (a fitted OpenPBR Surface)
  bool reset_material = false;
  bool pin = false;        // Pin as B: the shown material becomes the A/B comparison's B
  bool unpin = false;      // Unpin B
  std::optional<ShaderTarget> pin_fit;  // "B: Principled fit" / "B: OpenPBR fit": the shown material's fit as B
  FileSectionResult file;  // the File section: open, save, presets, recent, undo, redo
  std::optional<std::array<double, 3>> match_srgb;  // "Match colour...": the target, sRGB-encoded
};

// Draws the panel in rect (ImGui must be inside a frame) and edits state.
PanelActions control_panel(const Rect& rect, PreviewState& state, const PanelStatus& status,
                           const FileSectionInput& file);

}  // namespace skinlayer
