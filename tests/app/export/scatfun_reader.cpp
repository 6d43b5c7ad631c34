// SCATFUN v1 reader and pbrt-v3-style evaluation, from docs/exchange-formats.md §1 and the facts of
// pbrt-v3's algorithm given with this reader's brief.
#include "tests/app/export/scatfun_reader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace skinlayer::test {
namespace {

constexpr std::size_t kHeaderBytes = 64;

[[noreturn]] void fail(const std::string& rule) { throw std::runtime_error("SCATFUN: " + rule); }

template <typename T>
std::string str(const T& value) {
  std::ostringstream out;
  out.precision(9);
  out << value;
  return out.str();
}

std::string entry_name(std::size_t index, std::uint32_t n_mu) {
  return "entry (row " + str(index / n_mu) + ", col " + str(index % n_mu) + ")";
}

// The file is little-endian (sheet, header table), whatever the host's byte order.
std::uint32_t u32_at(std::string_view bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    value |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  }
  return value;
}
float f32_at(std::string_view bytes, std::size_t at) { return std::bit_cast<float>(u32_at(bytes, at)); }

// Catmull-Rom weights of x on the node array (pbrt-v3's CatmullRomWeights); nullopt outside [nodes[0], nodes[last]].
struct Weights {
  int offset;  // index of the node weights[0] belongs to (may be -1 or reach n: those weights are 0)
  std::array<double, 4> w;
};
std::optional<Weights> catmull_rom_weights(const std::vector<float>& nodes, double x) {
  const int n = static_cast<int>(nodes.size());
  if (!(x >= nodes.front() && x <= nodes.back())) return std::nullopt;
  // pbrt's FindInterval: the first i with nodes[i] > x, minus 1, clamped to [0, n-2]. At the doubled 0 this is the
  // second 0, whose interval to the next node has nonzero width.
  const int first = static_cast<int>(
      std::upper_bound(nodes.begin(), nodes.end(), x, [](double v, float node) { return v < node; }) - nodes.begin());
  const int idx = std::clamp(first - 1, 0, n - 2);
  const double x0 = nodes[idx], x1 = nodes[idx + 1];
  const double t = (x - x0) / (x1 - x0), t2 = t * t, t3 = t2 * t;
  Weights out{idx - 1, {0.0, 2 * t3 - 3 * t2 + 1, -2 * t3 + 3 * t2, 0.0}};
  if (idx > 0) {
    const double w0 = (t3 - 2 * t2 + t) * (x1 - x0) / (x1 - nodes[idx - 1]);
    out.w[0] = -w0;
    out.w[2] += w0;
  } else {
    const double w0 = t3 - 2 * t2 + t;
    out.w[0] = 0.0;
    out.w[1] -= w0;
    out.w[2] += w0;
  }
  if (idx + 2 < n) {
    const double w3 = (t3 - t2) * (x1 - x0) / (nodes[idx + 2] - x0);
    out.w[1] -= w3;
    out.w[3] = w3;
  } else {
    const double w3 = t3 - t2;
    out.w[1] -= w3;
    out.w[2] += w3;
    out.w[3] = 0.0;
  }
  return out;
}

// sum_k a[k] cos(k phi), cos(k phi) by the Chebyshev recurrence from cosPhi (pbrt-v3's Fourier).
double fourier_sum(const std::vector<double>& a, int m, double cos_phi) {
  double value = 0.0, cos_k_minus_1 = cos_phi, cos_k = 1.0;
  for (int k = 0; k < m; ++k) {
    value += a[k] * cos_k;
    const double cos_k_plus_1 = 2 * cos_phi * cos_k - cos_k_minus_1;
    cos_k_minus_1 = cos_k;
    cos_k = cos_k_plus_1;
  }
  return value;
}

// pbrt's CosDPhi: cosine of the azimuth difference of a and b, 1 if either has zero xy length.
double cos_d_phi(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double axy = a[0] * a[0] + a[1] * a[1], bxy = b[0] * b[0] + b[1] * b[1];
  if (axy == 0.0 || bxy == 0.0) return 1.0;
  return std::clamp((a[0] * b[0] + a[1] * b[1]) / std::sqrt(axy * bxy), -1.0, 1.0);
}

}  // namespace

ScatfunFile parse_scatfun(std::string_view bytes) {
  if (bytes.size() < kHeaderBytes) fail("file size: shorter than the 64-byte header (" + str(bytes.size()) + " bytes)");
  if (bytes.substr(0, 7) != "SCATFUN") fail("magic: the file does not start with \"SCATFUN\"");
  const unsigned version = static_cast<unsigned char>(bytes[7]);
  if (version != 1) fail("version byte must be exactly 1, got " + str(version));

  ScatfunFile file{};
  file.flags = u32_at(bytes, 8);
  file.n_mu = u32_at(bytes, 12);
  file.n_coeffs = u32_at(bytes, 16);
  file.m_max = u32_at(bytes, 20);
  file.n_channels = u32_at(bytes, 24);
  file.n_bases = u32_at(bytes, 28);
  file.n_metadata_bytes = u32_at(bytes, 32);
  file.n_parameters = u32_at(bytes, 36);
  file.n_parameter_values = u32_at(bytes, 40);
  file.eta = f32_at(bytes, 44);
  file.alpha[0] = f32_at(bytes, 48);
  file.alpha[1] = f32_at(bytes, 52);

  // Header rules (sheet §1, header table).
  if (file.flags != 1) fail("flags must be exactly 1 (is a BSDF), got " + str(file.flags));
  if (file.n_channels != 1 && file.n_channels != 3) fail("nChannels must be 1 or 3, got " + str(file.n_channels));
  if (file.n_bases != 1) fail("nBases must be 1, got " + str(file.n_bases));
  if (file.n_parameters != 0) fail("nParameters must be 0, got " + str(file.n_parameters));
  if (file.n_parameter_values != 0) fail("nParameterValues must be 0, got " + str(file.n_parameter_values));

  // Exact size (sheet §1, body): 64 + 4 nMu + 4 nMu^2 + 8 nMu^2 + 4 nCoeffs + nMetadataBytes. nMu above 2^24 would
  // need petabytes, and is refused before the product can overflow.
  const std::uint64_t n_mu = file.n_mu;
  if (n_mu > (std::uint64_t{1} << 24)) fail("file size: nMu = " + str(n_mu) + " implies an impossible size");
  const std::uint64_t n_entries = n_mu * n_mu;
  const std::uint64_t expected = kHeaderBytes + 4 * n_mu + 4 * n_entries + 8 * n_entries +
                                 4 * std::uint64_t{file.n_coeffs} + file.n_metadata_bytes;
  if (bytes.size() != expected) {
    fail("file size must be exactly 64 + 4 nMu + 12 nMu^2 + 4 nCoeffs + nMetadataBytes = " + str(expected) +
         " bytes, got " + str(bytes.size()));
  }

  const std::size_t n = file.n_mu, entries = n * n;
  std::size_t at = kHeaderBytes;
  file.mu.resize(n);
  for (std::size_t i = 0; i < n; ++i, at += 4) file.mu[i] = f32_at(bytes, at);
  file.cdf.resize(entries);
  for (std::size_t i = 0; i < entries; ++i, at += 4) file.cdf[i] = f32_at(bytes, at);
  file.offset.resize(entries);
  file.length.resize(entries);
  for (std::size_t i = 0; i < entries; ++i, at += 8) {  // (offset, length) pairs, offset first
    file.offset[i] = u32_at(bytes, at);
    file.length[i] = u32_at(bytes, at + 4);
  }
  file.coeffs.resize(file.n_coeffs);
  for (std::size_t i = 0; i < file.n_coeffs; ++i, at += 4) file.coeffs[i] = f32_at(bytes, at);
  file.metadata = std::string(bytes.substr(at, file.n_metadata_bytes));

  // Nodes (sheet §1, body item 1 and "the doubled zero"): from exactly -1 to exactly +1, ascending, two equal values
  // allowed once and only at 0.
  if (n < 2 || file.mu.front() != -1.0f || file.mu.back() != 1.0f) {
    fail("mu must start at exactly -1 and end at exactly +1 (nMu = " + str(n) +
         (n > 0 ? ", mu[0] = " + str(file.mu.front()) + ", mu[last] = " + str(file.mu.back()) : std::string()) + ")");
  }
  bool doubled_zero_seen = false;
  for (std::size_t i = 1; i < n; ++i) {
    const float a = file.mu[i - 1], b = file.mu[i];
    if (b > a) continue;
    if (b == a && a == 0.0f && !doubled_zero_seen) {
      doubled_zero_seen = true;
      continue;
    }
    fail("mu must be ascending with only one doubled 0: mu[" + str(i) + "] = " + str(b) + " after mu[" + str(i - 1) +
         "] = " + str(a));
  }

  // Entries (sheet §1, body items 3-4, header mMax, "the doubled zero", RGB).
  for (std::size_t i = 0; i < entries; ++i) {
    const std::uint64_t end = std::uint64_t{file.offset[i]} + std::uint64_t{file.n_channels} * file.length[i];
    if (end > file.n_coeffs) {
      fail(entry_name(i, file.n_mu) + ": offset + nChannels * length = " + str(end) +
           " exceeds nCoeffs = " + str(file.n_coeffs));
    }
    if (file.length[i] > file.m_max) {
      fail(entry_name(i, file.n_mu) + ": length " + str(file.length[i]) + " exceeds mMax = " + str(file.m_max));
    }
    const bool zero_node = file.mu[i / n] == 0.0f || file.mu[i % n] == 0.0f;
    if (zero_node && file.length[i] != 0) {
      fail(entry_name(i, file.n_mu) + ": an entry on a zero node must have length 0, has " + str(file.length[i]));
    }
    if (file.length[i] > 0 && !(file.coeffs[file.offset[i]] >= 0.0f)) {
      fail(entry_name(i, file.n_mu) + ": the Y channel's a0 must be >= 0, got " + str(file.coeffs[file.offset[i]]));
    }
  }

  // CDF rows (sheet §1, "CDF"): start at 0, never decrease.
  for (std::size_t row = 0; row < n; ++row) {
    const float* c = file.cdf.data() + row * n;
    if (c[0] != 0.0f) fail("cdf row " + str(row) + " must start at 0, got " + str(c[0]));
    for (std::size_t k = 1; k < n; ++k) {
      if (!(c[k] >= c[k - 1])) {
        fail("cdf row " + str(row) + " must be non-decreasing: cdf[" + str(k) + "] = " + str(c[k]) + " after " +
             str(c[k - 1]));
      }
    }
  }
  return file;
}

ScatfunFile read_scatfun(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("SCATFUN: cannot open " + path.string());
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error("SCATFUN: cannot read " + path.string());
  return parse_scatfun(bytes);
}

double scatfun_cdf_error(const ScatfunFile& file) {
  const std::size_t n = file.n_mu;
  std::vector<double> x(n), f(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = file.mu[i];
  double worst = 0.0;
  for (std::size_t row = 0; row < n; ++row) {
    // The row's channel-0 a0 per column, as written (an empty entry is 0).
    for (std::size_t col = 0; col < n; ++col) {
      const std::size_t e = row * n + col;
      f[col] = file.length[e] > 0 ? file.coeffs[file.offset[e]] : 0.0;
    }
    // pbrt-v3's IntegrateCatmullRom: segment [x0, x1] of width w adds w * ((f0 + f1) / 2 + (d0 - d1) / 12), d0 and
    // d1 the non-uniform central differences scaled by w, one-sided (f1 - f0) at the ends. The doubled 0 is a
    // segment of width 0.
    std::vector<double> expected(n, 0.0);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double x0 = x[k], x1 = x[k + 1], f0 = f[k], f1 = f[k + 1], w = x1 - x0;
      const double d0 = k > 0 ? w * (f1 - f[k - 1]) / (x1 - x[k - 1]) : f1 - f0;
      const double d1 = k + 2 < n ? w * (f[k + 2] - f0) / (x[k + 2] - x0) : f1 - f0;
      expected[k + 1] = expected[k] + w * ((f0 + f1) / 2 + (d0 - d1) / 12);
    }
    const double final_value = n > 0 ? std::abs(expected[n - 1]) : 0.0;
    const double scale = final_value > 0.0 ? final_value : 1.0;
    for (std::size_t k = 0; k < n; ++k) {
      worst = std::max(worst, std::abs(double{file.cdf[row * n + k]} - expected[k]) / scale);
    }
  }
  return worst;
}

std::array<double, 3> pbrt_fourier_f(const ScatfunFile& file, const std::array<double, 3>& wo,
                                     const std::array<double, 3>& wi, bool radiance) {
  const std::array<double, 3> minus_wi = {-wi[0], -wi[1], -wi[2]};
  const double mu_i = minus_wi[2], mu_o = wo[2];
  const double cos_phi = cos_d_phi(minus_wi, wo);
  const auto weights_i = catmull_rom_weights(file.mu, mu_i);
  const auto weights_o = catmull_rom_weights(file.mu, mu_o);
  if (!weights_i || !weights_o) return {0.0, 0.0, 0.0};

  // Blend the 4 x 4 neighbours; the entry (row = muO node, column = muI node) holds channel c's k-th coefficient at
  // coeffs[offset + c * length + k]. The blended series is as long as the longest one used.
  const int n = static_cast<int>(file.n_mu);
  const int channels = static_cast<int>(file.n_channels);
  std::vector<std::vector<double>> ak(channels, std::vector<double>(file.m_max, 0.0));
  int m_max = 0;
  for (int b = 0; b < 4; ++b) {
    for (int a = 0; a < 4; ++a) {
      const double weight = weights_i->w[a] * weights_o->w[b];
      if (weight == 0.0) continue;
      const std::size_t e = static_cast<std::size_t>((weights_o->offset + b) * n + (weights_i->offset + a));
      const int m = static_cast<int>(file.length[e]);
      m_max = std::max(m_max, m);
      for (int c = 0; c < channels; ++c) {
        for (int k = 0; k < m; ++k) ak[c][k] += weight * file.coeffs[file.offset[e] + c * m + k];
      }
    }
  }

  const double y = std::max(0.0, fourier_sum(ak[0], m_max, cos_phi));
  double scale = mu_i != 0.0 ? 1.0 / std::abs(mu_i) : 0.0;
  if (radiance && mu_i * mu_o > 0.0) {  // transmission: pbrt's radiance factor
    const double eta = mu_i > 0.0 ? 1.0 / file.eta : double{file.eta};
    scale *= eta * eta;
  }
  if (channels == 1) return {y * scale, y * scale, y * scale};
  // Channels Y, R, B; G rebuilt (sheet §1, RGB); pbrt clamps the RGB spectrum at 0.
  const double r = fourier_sum(ak[1], m_max, cos_phi);
  const double bl = fourier_sum(ak[2], m_max, cos_phi);
  const double g = 1.39829 * y - 0.100913 * bl - 0.297375 * r;
  return {std::max(0.0, r * scale), std::max(0.0, g * scale), std::max(0.0, bl * scale)};
}

}  // namespace skinlayer::test
