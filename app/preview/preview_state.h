// The previewer's value state: everything the user can change in the window, as plain values. The UI edits a copy
// each frame; the solver sees only the part that needs a solve (solve_request(): the material and the light's
// polar angle, at which the directional albedo is reported).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "app/preview/solve_request.h"
#include "app/render/scene.h"
#include "app/solution/material_solve.h"

namespace skinlayer {

// What a screenshot holds: the whole window (UI included, at framebuffer resolution), or one view's picture as the
// renderer drew it (without the UI's labels).
enum class ExportTarget { Window, Sphere, Plots };

struct LightState {
  double theta_degrees = 45.0;  // from the view direction, in [0, kMaxLightThetaDegrees]
  double phi_degrees = 180.0;   // azimuth in the picture plane, in [-180, 180]; 180 = light from the left
};

// How the sphere is lit (app/render/renderer.h): the directional light, an environment, or both.
struct LightingState {
  std::string environment;      // empty: none; "furnace", "studio", "sky", or a .hdr path
  double rotate_degrees = 0.0;  // about the vertical, in [-180, 180]
  double ev = 0.0;              // radiance x 2^EV, in [kMinStops, kMaxStops]
  EnvironmentBackground background = EnvironmentBackground::Show;
  bool directional = true;  // the directional light too
  ToneMap tone_map = ToneMap::Exponential;
  std::string typed_path;  // the panel's .hdr path field (what Load would open)
  bool operator==(const LightingState&) const = default;

  // The renderer's view of the environment.
  EnvironmentView view() const;
};

// A/B comparison: a pinned material B shown right of a split line across the sphere, beside the edited A, and as
// an outline over A's lobes.
struct ComparisonState {
  std::optional<ColorMaterial> pinned;  // B; unset: no comparison
  double split = 0.5;                   // where the line crosses the sphere's view: 0 left edge .. 1 right edge
  // What B is, as the sphere's label says it: "B (pinned)", or a fitted shader's ("B (Principled fit)"), whose
  // tables hold the fit's BRDF under an index-matched top (app/solution/fitted_tables.h).
  std::string label = "B (pinned)";
  bool operator==(const ComparisonState&) const = default;
};

struct ViewOptions {
  ViewKind view = ViewKind::Both;  // which views share the picture area
  bool log_lobes = false;          // lobe radius: linear in the BSDF, or log over LobeView::decades decades
  double exposure_stops = 0.0;     // the tone map's linear exposure is 2^stops; in [kMinStops, kMaxStops]
  std::optional<SubsurfaceModel> plot_model;  // the lobe plots' model; unset = the sphere's (material.model)
  // The sphere's size, for the translucency: its subsurface light spreads by the material's profile (issue 43). 40 mm
  // is a cheek's or a forehead's radius of curvature.
  double sphere_radius_mm = 40.0;  // in [kMinSphereRadiusMm, kMaxSphereRadiusMm]
  bool translucency = true;
};

inline constexpr double kMinSphereRadiusMm = 1.0;
inline constexpr double kMaxSphereRadiusMm = 1000.0;

struct ExportOptions {
  ExportTarget target = ExportTarget::Window;
  std::string path;  // empty: a timestamped name in the current folder (timestamped_png_name()) at each save
};

// The paper's default material (σ 0.5, η 1.4, T 0.2, Ω 1 in every channel, g 0.8, bottom air), from core's
// parameter table.
ColorMaterial paper_default_material();

struct PreviewState {
  ColorMaterial material = paper_default_material();
  LightState light;
  ViewOptions view;
  ExportOptions export_options;
  LightingState lighting;
  ComparisonState comparison;
  bool show_help = false;  // the F1 overlay
  std::array<float, 3> match_color = {0.8f, 0.6f, 0.5f};  // the "Match colour..." picker's colour, sRGB-encoded
};

inline constexpr double kMaxLightThetaDegrees = 89.9;  // as `skinlayer render --light-theta`
inline constexpr double kMinStops = -8.0;
inline constexpr double kMaxStops = 8.0;

// The state with the material reset to the paper's default; light, view and export settings are kept.
PreviewState reset_material(PreviewState state);

// The request the solver needs for this state: the material, and the light's polar angle in radians.
SolveRequest solve_request(const PreviewState& state);

// 2^stops.
double exposure_multiplier(const ViewOptions& view);

}  // namespace skinlayer
