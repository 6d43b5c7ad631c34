// The RGL measured-BSDF "tensor file" (Dupuy & Jakob 2018) of a solved material, for pbrt-v4's `measured` material
// and Mitsuba 3's `measured` plugin (issue 26). The readers reconstruct, for a camera direction w_o and a light w_i
// on the same side, with m = normalize(w_o + w_i) and u(theta) = sqrt(2 theta / pi), u(phi) = phi / 2pi + 1/2:
//   f(w_o, w_i) = S(xi | phi_o, theta_o) D~(u_m) / (4 sigma~(u_o) cos theta_i),   xi = vndf^-1(u_m | phi_o, theta_o),
// with D~ and sigma~ the bilinear `ndf` and `sigma` tables, S bilinear in xi and linear between the theta_o slices,
// and the warp that of core/sampling/piecewise_linear_2d.h. This writer chooses
//   D(m) = (1 - w) Beckmann_sigma(m) + w / pi   (the top interface's lobe, and a floor w that reaches every pair),
//   sigma(w) = int D(m) max(0, w . m) dm,   vndf(u_m | w_o) = 2 pi^2 u_theta sin(theta_m) max(0, w_o . m) D(m),
// and at each sample node xi of an n x n grid stores S = f(w_o, w_i) cos theta_i 4 sigma~(u_o) / D~(u_m) with
// u_m = vndf(xi) and w_i = reflect(w_o, m): the reconstruction is exact at the nodes. Reflection only.
#pragma once

#include <functional>
#include <string>

#include "app/render/material_solve.h"

namespace skinlayer {

// The grid (7.6 MB): measured against eval at random pairs, the default material's BRDF is within 2% at 98.9% of
// them and within 8% at all (tests/app/export/rgl_export_test.cpp); more slices or samples barely help, and the
// worst pairs graze near the mirror.
struct RglOptions {
  int thetas = 32;     // theta_o slices, (pi/2) sin((pi/2) k / T): denser toward grazing
  int samples = 80;    // n: sample nodes per side of the xi grid
  int ndf_size = 64;   // nodes per side of the ndf, sigma and vndf grids
  double floor = 0.3;  // w: the uniform floor's share of the NDF (0.1 left grazing backscatter 33% off)
};

// The RGB form (the `rgb` field, which Mitsuba 3's RGB variants read), linear sRGB per channel of the material's
// BRDF (surface and subsurface) in 1/sr. progress(done, total) counts theta_o slices.
std::string rgl_rgb_file(const ColorTables& tables, const RglOptions& options, const std::string& description,
                         const std::function<void(int, int)>& progress = {});

}  // namespace skinlayer
