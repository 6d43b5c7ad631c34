// The tabulated Fourier BSDF file, "SCATFUN" version 1: what layerlab writes and pbrt-v3's "fourier" material reads
// (docs/exchange-formats.md §1; pbrt-v4 and Mitsuba 3 do not read it). Little-endian:
//   64-byte header: "SCATFUN", version 1 (uint8); uint32 flags (1: a BSDF), nMu, nCoeffs, mMax, nChannels, nBases (1),
//     nMetadataBytes, nParameters (0), nParameterValues (0); float32 eta (n_below / n_above), alpha[2] (the top's and
//     the bottom's roughness, informational), 2 unused;
//   float32 mu[nMu] (ascending, -1 .. 1, the doubled 0); float32 cdf[nMu][nMu]; uint32 (offset, length)[nMu][nMu]
//     (offsets in floats); float32 coeffs[nCoeffs]; the metadata bytes.
// Entry (row, col): light travelling along the row's direction leaves along the column's, both mu the cosine of the
// propagation direction against the downward axis (mu > 0 travels down); its nChannels blocks of `length` floats are
// the cosine series a_0 + sum_k a_k cos(k phi) of f |mu_col| (f the radiance BSDF, 1/sr), phi = 0 the mirror and
// straight-through direction. Channels: 1 (grey), or 3: Y, R, B (Y = 0.212671 R + 0.715160 G + 0.072169 B).
// cdf[row] is the running integral over the column mu of the row's Y a_0, each segment integrated as the Catmull-Rom
// spline a reader interpolates with (pbrt-v3's IntegrateCatmullRom), computed from the float32 values written.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skinlayer {

inline constexpr std::size_t kScatfunHeaderBytes = 64;

struct ScatfunTable {
  std::vector<float> mu;  // nMu nodes
  int channels = 1;       // 1 or 3
  // Entry (row, col) at row * nMu + col: `channels` blocks of one length each, channel after channel; empty for none.
  std::vector<std::vector<float>> entries;
  float eta = 1.0f;
  std::array<float, 2> alpha = {0.0f, 0.0f};
  std::string metadata;
};

// The file's bytes. Throws std::invalid_argument for a table that breaks the format's rules (mu not from -1 to 1 or
// not ascending, an entry not a multiple of the channel count, a negative Y a_0).
std::string encode_scatfun(const ScatfunTable& table);

// True when the bytes start as a SCATFUN file.
bool is_scatfun(std::string_view bytes);
// The metadata block of a SCATFUN file's bytes (skinlayer writes the material file's JSON there); nullopt for a file
// shorter than its header says.
std::optional<std::string_view> scatfun_metadata(std::string_view bytes);

// The polar node angles (radians) of a grid of `nodes` per hemisphere, denser at both ends:
//   theta_j = (pi/2) (t - 0.8 sin(2 pi t) / 2 pi),   t = j / (nodes - 1),
// whose spacing is 0.2 of a uniform grid's at the normal and at grazing and 1.8 of it at 45 degrees
// (theta_{nodes-1} = pi/2: mu = 0). pbrt-v3 interpolates Catmull-Rom in mu, and two things defeat it at the ends:
// near the normal a lobe that is off the normal has a first azimuthal mode ~ sin theta = sqrt(1 - mu^2); near
// grazing f |mu| falls to 0 at the doubled zero node. With uniform theta nodes (64) a thin layer's transmission was
// 3.6% off 0.5 degrees from the normal and its reflection +7.7% / -62% 2 and 0.5 degrees from grazing; with these,
// 0.7% and within 0.01% up to 89 degrees (tests/app/export/scatfun_export_test.cpp). What remains: the first node
// is 0.29 degrees from the normal, and within 0.5 degrees of grazing the doubled zero still pulls the value down.
std::vector<double> scatfun_node_angles(int nodes);
// The file's mu grid of 2 nodes entries: -cos theta_0 = -1, ..., -cos theta_{nodes-2}, 0, 0, cos theta_{nodes-2}, ...,
// cos theta_0 = 1.
std::vector<float> scatfun_mu_grid(int nodes);

}  // namespace skinlayer
