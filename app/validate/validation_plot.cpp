#include "app/validate/validation_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "app/figures/canvas.h"
#include "app/figures/xy_plot.h"
#include "app/material/material_flag_text.h"
#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer::validation {
namespace {

using figures::Canvas;
using figures::ErrorBarPoint;
using figures::LevelBar;
using figures::XyPlot;
using figures::XySeries;

constexpr int kHeader = 64;
constexpr int kPanelHeight = 330;
constexpr int kPlaneWidth = 720;
constexpr int kAcrossWidth = 420;
constexpr double kErrorBarSigmas = 2.0;

// The solver's BSDF on one exit side at theta_o and phi (radians), in 1/sr; reflection includes the surface term.
double solver_bsdf(const SetResult& result, ExitSide side, double theta_o, double phi) {
  const double theta_i = degrees_to_radians(result.set.theta_i_deg);
  if (side == ExitSide::Transmitted) return result.tables.btdf(theta_i, theta_o, phi);
  return result.tables.brdf_subsurface(theta_i, theta_o, phi) +
         brdf_surface(result.set.material, theta_i, theta_o, phi);
}

// The signed plotting angle of a bin's centre: negative on the back side, positive forward and across.
double signed_centre(const ValidationBin& bin) {
  const double centre = 0.5 * (bin.theta_min_deg + bin.theta_max_deg);
  return bin.plane == BinPlane::Back ? -centre : centre;
}

XyPlot panel(const SetResult& result, ExitSide side, bool across) {
  const figures::Rgba color = figures::curve_color(across ? 1 : 0);
  const figures::Rgba mc_color{20, 20, 20, 255};
  XySeries curve{across ? "solver, φ 90°" : "solver, plane of incidence", color, {}, {}, {}};
  for (int d = across ? 0 : -90; d <= 90; ++d) {
    const double phi = across ? 0.5 * kPi : d < 0 ? 0.0 : kPi;
    curve.curve.push_back({static_cast<double>(d), solver_bsdf(result, side, degrees_to_radians(std::abs(d)), phi)});
  }
  XySeries levels{"solver, bin average", color, {}, {}, {}};
  XySeries points{"Monte Carlo ± 2 SE", mc_color, {}, {}, {}};
  for (std::size_t k = 0; k < result.bins.size(); ++k) {
    const ValidationBin& bin = result.bins[k];
    if (bin.side != side || (bin.plane == BinPlane::Across) != across || bin.peak != nullptr) continue;
    const Comparison& c = result.bin_comparisons[k];
    const double x = signed_centre(bin);
    const double half = 0.5 * (bin.theta_max_deg - bin.theta_min_deg);
    levels.levels.push_back(LevelBar{x - half, x + half, c.solver});
    points.points.push_back(ErrorBarPoint{x, c.monte_carlo, kErrorBarSigmas * c.standard_error});
  }
  XyPlot plot;
  const std::string quantity = side == ExitSide::Reflected ? "BRDF (surface + subsurface)" : "BTDF";
  plot.title = across ? quantity + ", across (φ 90°)" : quantity + ", plane of incidence";
  plot.x_label = across ? "θo [°]" : "θo [°]   (back, φ 0°: negative · forward, φ 180°: positive)";
  plot.y_label = "1/sr";
  plot.x_min = across ? 0.0 : -90.0;
  plot.x_max = 90.0;
  plot.x_tick = across ? 15.0 : 30.0;
  plot.series = {curve, levels, points};
  plot.width = across ? kAcrossWidth : kPlaneWidth;
  plot.height = kPanelHeight;
  return plot;
}

}  // namespace

Image draw_validation_plot(const SetResult& result, const figures::Font& font) {
  const bool transmits = std::any_of(result.bins.begin(), result.bins.end(),
                                     [](const ValidationBin& b) { return b.side == ExitSide::Transmitted; });
  const int rows = transmits ? 2 : 1;
  Canvas canvas(kPlaneWidth + kAcrossWidth, kHeader + rows * kPanelHeight, figures::kPlotBackground);
  char title[256];
  std::snprintf(title, sizeof title, "%s: %s, θi %g°", result.set.name.c_str(), result.set.description.c_str(),
                result.set.theta_i_deg);
  canvas.text(font, title, {canvas.width() / 2.0, 24}, 18, figures::kPlotInk, figures::Align::Center);
  canvas.text(font, material_to_flags(result.set.material), {canvas.width() / 2.0, 48}, 13, figures::kPlotMuted,
              figures::Align::Center);
  int row = 0;
  for (const ExitSide side : {ExitSide::Reflected, ExitSide::Transmitted}) {
    if (side == ExitSide::Transmitted && !transmits) continue;
    const int y = kHeader + row * kPanelHeight;
    canvas.blit(figures::draw_xy_plot(panel(result, side, false), font), 0, y);
    canvas.blit(figures::draw_xy_plot(panel(result, side, true), font), kPlaneWidth, y);
    ++row;
  }
  return canvas.image();
}

}  // namespace skinlayer::validation
