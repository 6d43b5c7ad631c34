// An independent reader of the tabulated Fourier BSDF format "SCATFUN" version 1 (layerlab writes it, pbrt-v3's
// `fourier` material reads it), written for the tests from docs/exchange-formats.md §1 alone. It shares no
// code with skinlayer's writer: it includes nothing from core/ or app/.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace skinlayer::test {

struct ScatfunFile {
  std::uint32_t flags, n_mu, n_coeffs, m_max, n_channels, n_bases, n_metadata_bytes, n_parameters, n_parameter_values;
  float eta;
  float alpha[2];
  std::vector<float> mu;                      // n_mu
  std::vector<float> cdf;                     // n_mu * n_mu, cdf[row * n_mu + k]
  std::vector<std::uint32_t> offset, length;  // n_mu * n_mu each, entry index row * n_mu + col
  std::vector<float> coeffs;                  // n_coeffs
  std::string metadata;
};

// Parses a SCATFUN v1 file and enforces every structural rule a strict reader does; throws std::runtime_error naming
// the rule that failed: magic "SCATFUN" and version byte exactly 1; flags exactly 1; nChannels 1 or 3; nBases 1;
// nParameters 0 and nParameterValues 0; the exact file size 64 + 4 nMu + 4 nMu^2 + 8 nMu^2 + 4 nCoeffs +
// nMetadataBytes; mu ascending with one doubled 0 allowed, from exactly -1 to exactly +1; each entry's
// offset + nChannels * length <= nCoeffs and length <= mMax; length 0 on every entry whose row or column is a zero
// node; each CDF row starting at 0 and non-decreasing; the Y channel's a0 >= 0 on every non-empty entry.
ScatfunFile parse_scatfun(std::string_view bytes);

// Reads the file at path, then parse_scatfun.
ScatfunFile read_scatfun(const std::filesystem::path& path);

// The stored CDF against the one the sheet prescribes from the written floats: per row, cdf[row][0] = 0 and
// cdf[row][k+1] = cdf[row][k] + the Catmull-Rom integral of that row's channel-0 a0 over the column mu between nodes
// k and k+1 (pbrt-v3's IntegrateCatmullRom). Returns the worst absolute difference divided by the row's final
// (recomputed) value; a row whose final value is 0 counts its absolute difference.
double scatfun_cdf_error(const ScatfunFile& file);

// What pbrt-v3's FourierBSDF::f(wo, wi) returns, in pbrt's local frame (+z the shading normal, both vectors unit and
// pointing away from the surface: wi toward the light, wo toward the camera), in double precision. Returns
// {R, G, B} (grey files: all three = Y). radiance = true is TransportMode::Radiance.
std::array<double, 3> pbrt_fourier_f(const ScatfunFile& file, const std::array<double, 3>& wo,
                                     const std::array<double, 3>& wi, bool radiance = true);

}  // namespace skinlayer::test
