// The polar lobe plot's numbers on the CPU: the BSDF at a point of the plot (the value under the mouse) and the
// plot's radius scale, mirroring shaders/lobe.frag. The plot lies in the plane of incidence: reflection above the
// surface line (y > 0), transmission below; x > 0 is the forward side (phi = pi), x < 0 the back side (phi = 0);
// theta_o is measured from the normal on the point's side.
#pragma once

#include <array>

#include "app/render/renderer.h"
#include "app/solution/material_solve.h"

namespace skinlayer {

struct LobeSample {
  bool reflection = true;         // above the surface line: BRDF; below: BTDF
  double theta_o = 0.0;           // radians from the normal of the point's side
  double phi = 0.0;               // 0 (back side) or pi (forward side)
  double surface = 0.0;           // top interface BRDF [1/sr] (grey; 0 below the line)
  std::array<double, 3> total{};  // per channel: brdf_total or btdf_total [1/sr]
  double plotted_total() const { return (total[0] + total[1] + total[2]) / 3.0; }  // what the plot draws
  double plotted_subsurface() const { return plotted_total() - surface; }
};

// The BSDF in the direction of plot point (x, y), in plot radii, for light at theta_i (radians).
LobeSample probe_lobe(const ColorTables& tables, double theta_i, double x, double y);

// The plot radius of BSDF value f (linear: f / peak; log: 1 + log10(f / peak) / decades, at least 0), and the value
// drawn at radius r (the inverse, for labelling the rings).
double lobe_radius(const LobeView& view, double f);
double lobe_value_at_radius(const LobeView& view, double r);

}  // namespace skinlayer
