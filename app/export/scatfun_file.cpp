#include "app/export/scatfun_file.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>

namespace skinlayer {

namespace {

static_assert(std::endian::native == std::endian::little, "SCATFUN files are little-endian");
constexpr std::string_view kMagic = "SCATFUN";
constexpr std::uint8_t kVersion = 1;
constexpr std::uint32_t kFlagBsdf = 1;
constexpr std::size_t kMetadataSizeAt = 32;  // the header's nMetadataBytes

template <class T>
void append(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

// The integral of each segment of the Catmull-Rom spline through (x, f), as a reader interpolates: for
// [x_k, x_{k+1}] of width w, w ((f_k + f_{k+1}) / 2 + (d_k - d_{k+1}) / 12), with the end derivatives (scaled by w)
// from central differences over the neighbouring nodes, one-sided at the ends. Running sums, cdf[0] = 0.
std::vector<float> catmull_rom_running_integral(const std::vector<float>& x, const std::vector<float>& f) {
  const std::size_t n = x.size();
  std::vector<float> cdf(n, 0.0f);
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double x0 = x[k], x1 = x[k + 1], f0 = f[k], f1 = f[k + 1], width = x1 - x0;
    const double d0 = k > 0 ? width * (f1 - f[k - 1]) / (x1 - x[k - 1]) : f1 - f0;
    const double d1 = k + 2 < n ? width * (f[k + 2] - f0) / (x[k + 2] - x0) : f1 - f0;
    sum += width * ((f0 + f1) * 0.5 + (d0 - d1) / 12.0);
    cdf[k + 1] = static_cast<float>(sum);
  }
  return cdf;
}

}  // namespace

std::string encode_scatfun(const ScatfunTable& table) {
  const std::size_t n = table.mu.size();
  if (n < 2 || table.mu.front() != -1.0f || table.mu.back() != 1.0f || !std::ranges::is_sorted(table.mu)) {
    throw std::invalid_argument("SCATFUN: mu must ascend from exactly -1 to exactly 1");
  }
  if (table.channels != 1 && table.channels != 3) throw std::invalid_argument("SCATFUN: 1 or 3 channels");
  if (table.entries.size() != n * n) throw std::invalid_argument("SCATFUN: need nMu x nMu entries");
  std::vector<std::uint32_t> offsets(n * n), lengths(n * n);
  std::uint32_t total = 0, longest = 0;
  for (std::size_t e = 0; e < n * n; ++e) {
    const std::vector<float>& entry = table.entries[e];
    if (entry.size() % table.channels != 0) throw std::invalid_argument("SCATFUN: an entry's channels differ");
    if (!entry.empty() && !(entry[0] >= 0.0f)) throw std::invalid_argument("SCATFUN: a negative Y a_0");
    offsets[e] = total;
    lengths[e] = static_cast<std::uint32_t>(entry.size() / table.channels);
    total += static_cast<std::uint32_t>(entry.size());
    longest = std::max(longest, lengths[e]);
  }

  std::string bytes;
  bytes.reserve(kScatfunHeaderBytes + 16 * n * n + 4 * std::size_t{total} + table.metadata.size());
  bytes.append(kMagic);
  append(bytes, kVersion);
  for (std::uint32_t field :
       {kFlagBsdf, static_cast<std::uint32_t>(n), total, longest, static_cast<std::uint32_t>(table.channels),
        std::uint32_t{1}, static_cast<std::uint32_t>(table.metadata.size()), std::uint32_t{0}, std::uint32_t{0}}) {
    append(bytes, field);
  }
  for (float field : {table.eta, table.alpha[0], table.alpha[1], 0.0f, 0.0f}) append(bytes, field);
  for (float mu : table.mu) append(bytes, mu);
  std::vector<float> a0(n);
  for (std::size_t row = 0; row < n; ++row) {
    for (std::size_t col = 0; col < n; ++col) {
      const std::vector<float>& entry = table.entries[row * n + col];
      a0[col] = entry.empty() ? 0.0f : entry[0];
    }
    for (float value : catmull_rom_running_integral(table.mu, a0)) append(bytes, value);
  }
  for (std::size_t e = 0; e < n * n; ++e) {
    append(bytes, offsets[e]);
    append(bytes, lengths[e]);
  }
  for (const std::vector<float>& entry : table.entries) {
    bytes.append(reinterpret_cast<const char*>(entry.data()), entry.size() * sizeof(float));
  }
  bytes.append(table.metadata);
  return bytes;
}

bool is_scatfun(std::string_view bytes) { return bytes.starts_with(kMagic); }

std::optional<std::string_view> scatfun_metadata(std::string_view bytes) {
  if (bytes.size() < kScatfunHeaderBytes) return std::nullopt;
  std::uint32_t size = 0;
  std::memcpy(&size, bytes.data() + kMetadataSizeAt, sizeof(size));
  if (size > bytes.size() - kScatfunHeaderBytes) return std::nullopt;
  return bytes.substr(bytes.size() - size);
}

std::vector<double> scatfun_node_angles(int nodes) {
  std::vector<double> theta(nodes);
  constexpr double kEnds = 0.8;  // 0: uniform in theta; 1 would make the end nodes coincide in float
  for (int j = 0; j < nodes; ++j) {
    const double t = static_cast<double>(j) / (nodes - 1);
    theta[j] = (std::numbers::pi / 2) * (t - kEnds * std::sin(2.0 * std::numbers::pi * t) / (2.0 * std::numbers::pi));
  }
  theta.back() = std::numbers::pi / 2;  // exactly, for mu = 0
  return theta;
}

std::vector<float> scatfun_mu_grid(int nodes) {
  const std::vector<double> theta = scatfun_node_angles(nodes);
  std::vector<float> mu(2 * static_cast<std::size_t>(nodes));
  for (int j = 0; j + 1 < nodes; ++j) {
    mu[j] = static_cast<float>(-std::cos(theta[j]));
    mu[2 * nodes - 1 - j] = static_cast<float>(std::cos(theta[j]));
  }
  mu[nodes - 1] = mu[nodes] = 0.0f;
  mu.front() = -1.0f;
  mu.back() = 1.0f;
  return mu;
}

}  // namespace skinlayer
