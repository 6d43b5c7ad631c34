// The RGL measured-BSDF "tensor file" (Dupuy & Jakob 2018) of a solved material, for pbrt-v4's `measured` material
// and Mitsuba 3's `measured` plugin (issue 26). The readers reconstruct, for a camera direction w_o and a light w_i
// on the same side, with m = normalize(w_o + w_i) and u(theta) = sqrt(2 theta / pi), u(phi) = phi / 2pi + 1/2:
//   f(w_o, w_i) = S(xi | phi_o, theta_o) D~(u_m) / (4 sigma~(u_o) cos theta_i),   xi = vndf^-1(u_m | phi_o, theta_o),
// with D~ and sigma~ the bilinear `ndf` and `sigma` tables, S bilinear in xi and linear between the theta_o slices
// (and wavelengths), and the warp that of core/sampling/piecewise_linear_2d.h. pbrt-v4 computes exactly this;
// Mitsuba 3 returns f cos theta_i (it applies D~/(4 sigma~) because `jacobian` is 1) and does not clamp S at 0.
//
// This writer chooses
//   D(m) = (1 - w) Beckmann_sigma(m) + w / pi   (the top interface's lobe, and a floor w that reaches every pair),
//   sigma(w) = int D(m) max(0, w . m) dm,
// and at each node xi of an n x n grid stores S = f(w_o, w_i) cos theta_i 4 sigma~(u_o) / D~(u_m) with
// u_m = vndf(xi) and w_i = reflect(w_o, m), so the reconstruction is exact at the nodes. The `vndf` table only places
// the nodes (both readers use it as a warp and its density for sampling, never as a factor of f), so it need not be
// the physical visible-normal density: it is the same for every theta_o, a mixture on the u square of
//   0.5 J cos(theta_m) Beckmann_sigma(m) + 0.2 J cos(theta_m) / pi + 0.3,   J = 2 pi^2 u_theta sin(theta_m)
// (each term integrates to 1 over the square): half the nodes in the surface lobe, the rest spread evenly in u, so
// that the subsurface lobe and grazing pairs keep nodes, and a half vector has the same xi in every theta_o slice.
// The physical VNDF instead leaves the forward side of grazing views nearly empty: with it a sharp thin layer was
// within 2% at only 87.8% of the pairs, 36% off at worst (measured). Reflection only: the format has no transmission.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

namespace skinlayer {

// The grid (measured by tests/app/export/rgl_export_test.cpp): the presets, the default material and a sharp thin
// layer are within 2% of eval at >= 99% of random pairs and within 5% at all. The ndf table needs its 128 nodes for
// jade's sigma 0.08 (at 64 its peak's flank was 4% off); more vndf nodes do not help.
struct RglOptions {
  static constexpr int kMinSamples = 16, kMaxSamples = 192;
  int thetas = 32;     // theta_o slices, denser toward grazing (rgl_export.cpp)
  int samples = 64;    // n: sample nodes per side of the xi grid, [kMinSamples, kMaxSamples]
  int vndf_size = 48;  // nodes per side of the vndf (node placement) grid
  int ndf_size = 128;  // nodes per side of the ndf and sigma grids
  double floor = 0.5;  // w: the uniform floor's share of the NDF
};

// The channels a file holds and the BRDF that fills them.
struct RglChannels {
  // Empty: the rgb form (three channels, linear sRGB). Otherwise the spectral form's wavelengths, ascending, nm.
  std::vector<double> wavelengths;
  // Per channel, its share of the luminance table (which the readers sample by): Y = sum_k weight_k value_k.
  std::vector<double> luminance_weights;
  // The BRDF in 1/sr of every channel at once for light theta_i, camera theta_o and azimuth difference phi (radians).
  // Called from the parallel-for's threads.
  std::function<void(double theta_i, double theta_o, double phi, std::span<double> values)> brdf;
  double top_sigma = 0.3;  // the top interface's Beckmann roughness, for the NDF
};

// The file's bytes. progress(done, total) counts theta_o slices, from the parallel-for's threads one at a time.
std::string rgl_file(const RglChannels& channels, const RglOptions& options, const std::string& description,
                     const std::function<void(int, int)>& progress = {});

}  // namespace skinlayer
