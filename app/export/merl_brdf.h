// The MERL BRDF ".binary" (Matusik et al. 2003; docs/exchange-formats.md §2): reflection only, isotropic,
// RGB, tabulated on the Rusinkiewicz half/difference angles, 90 (theta_h, square-root spacing) x 90 (theta_d) x 180
// (phi_d in [0, pi)) bins. Layout: three int32 (90, 90, 180), then 3 x 1,458,000 float64, all red, then all green,
// then all blue, each value the plain BRDF f (1/sr, no cosine) times the format's channel scale (1500, 1500/1.15,
// 1500/1.66); a bin whose directions fall below the horizon holds a negative value. 34,992,012 bytes in all.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

inline constexpr int kMerlThetaH = 90, kMerlThetaD = 90, kMerlPhiD = 180;
inline constexpr std::size_t kMerlBins = std::size_t{kMerlThetaH} * kMerlThetaD * kMerlPhiD;  // per channel
inline constexpr std::size_t kMerlBytes = 3 * sizeof(std::int32_t) + 3 * kMerlBins * sizeof(double);
inline constexpr std::array<double, 3> kMerlScale = {1500.0, 1500.0 / 1.15, 1500.0 / 1.66};
// What a bin below the horizon holds (readers treat any negative value as "no data").
inline constexpr double kMerlBelowHorizon = -1.0;

// The directions at the centre of a bin (indices within [0, 90) x [0, 90) x [0, 180)), both pointing away from the
// surface (+z), as unit vectors in the frame with the half vector in the x-z plane (phi_h = 0): the difference
// vector d at (theta_d, phi_d) rotated by theta_h about y gives omega_i, and omega_o is omega_i mirrored about h.
struct MerlBinDirections {
  Vec3 incident;  // omega_i
  Vec3 outgoing;  // omega_o
  bool above_horizon() const { return incident.z() > 0.0 && outgoing.z() > 0.0; }
};
MerlBinDirections merl_bin_directions(int theta_h, int theta_d, int phi_d);

// The file's bytes: brdf(omega_i, omega_o) gives the RGB BRDF in 1/sr for directions above the horizon.
// progress(done, total) is called now and then with the theta_h rows finished (optional). The rows run through
// parallel_for (app/process/parallel_for.h) when it is given; brdf must then be safe to call from several threads.
using RgbBrdf = std::function<std::array<double, 3>(const Vec3& incident, const Vec3& outgoing)>;
std::string encode_merl(const RgbBrdf& brdf, const std::function<void(int, int)>& progress = {},
                        const std::function<void(int, const std::function<void(int)>&)>& parallel_for = {});

}  // namespace skinlayer
