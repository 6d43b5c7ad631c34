#include "app/export/rgl_export.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "app/export/tensor_file.h"
#include "app/process/parallel_for.h"
#include "core/conventions.h"
#include "core/interfaces/microfacet.h"
#include "core/sampling/piecewise_linear_2d.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

// The format's coordinates: u(theta) = sqrt(2 theta / pi) and u(phi) = phi / 2pi + 1/2, and their inverses.
double theta_of_u(double u) { return 0.5 * kPi * u * u; }
double u_of_theta(double theta) { return std::sqrt(2.0 * theta / kPi); }
double phi_of_u(double u) { return 2.0 * kPi * (u - 0.5); }

// The node placement's shares (rgl_export.h): surface lobe, cosine floor, uniform on the u square.
constexpr double kPlaceLobe = 0.5, kPlaceCosine = 0.2, kPlaceUniform = 0.3;

// A bilinear table on [0,1]^2 (x fastest), as the readers interpolate `ndf` and `sigma`.
struct Table2 {
  int nx = 0, ny = 0;
  std::vector<float> values;
  double at(double ux, double uy) const {
    const double px = std::clamp(ux, 0.0, 1.0) * (nx - 1), py = std::clamp(uy, 0.0, 1.0) * (ny - 1);
    const int x = std::min(static_cast<int>(px), nx - 2), y = std::min(static_cast<int>(py), ny - 2);
    const double s = px - x, t = py - y;
    const auto v = [&](int i, int j) { return static_cast<double>(values[static_cast<std::size_t>(j) * nx + i]); };
    return (1.0 - t) * ((1.0 - s) * v(x, y) + s * v(x + 1, y)) + t * ((1.0 - s) * v(x, y + 1) + s * v(x + 1, y + 1));
  }
};

// The NDF: the top interface's Beckmann lobe with a uniform floor, normalized as int D(m) cos theta_m dm = 1. [1/sr]
double ndf(double cos_m, double sigma, double floor) {
  return (1.0 - floor) * beckmann_ndf(cos_m, sigma) + floor / kPi;
}

// sigma(theta) = int D(m) max(0, w . m) dm for w at polar angle theta: the NDF's projected area toward w.
double projected_area(double theta, double sigma, double floor) {
  const QuadratureRule polar = gauss_legendre(256, 0.0, 0.5 * kPi);
  constexpr int kAzimuths = 128;
  const Vec3 w = direction_from_angles(theta, 0.0);
  double sum = 0.0;
  for (int a = 0; a < polar.size(); ++a) {
    const double t = polar.nodes[a], d = ndf(std::cos(t), sigma, floor);
    double ring = 0.0;
    for (int k = 0; k < kAzimuths; ++k)
      ring += std::max(0.0, w.dot(direction_from_angles(t, 2.0 * kPi * (k + 0.5) / kAzimuths)));
    sum += polar.weights[a] * std::sin(t) * d * ring * (2.0 * kPi / kAzimuths);
  }
  return sum;
}

// A table that depends on u(theta) only, on an n x n grid.
Table2 radial_table(int n, const std::function<double(double theta)>& value) {
  Table2 table{n, n, std::vector<float>(static_cast<std::size_t>(n) * n)};
  for (int i = 0; i < n; ++i) {
    const float v = static_cast<float>(value(theta_of_u(static_cast<double>(i) / (n - 1))));
    for (int j = 0; j < n; ++j) table.values[static_cast<std::size_t>(j) * n + i] = v;
  }
  return table;
}

// The node placement density on the u square (rgl_export.h), the same for every theta_o.
std::vector<double> placement(int n, double sigma) {
  std::vector<double> density(static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / (n - 1), theta_m = theta_of_u(u), c = std::cos(theta_m);
    const double jacobian = 2.0 * kPi * kPi * u * std::sin(theta_m);
    const double value =
        kPlaceLobe * jacobian * c * beckmann_ndf(c, sigma) + kPlaceCosine * jacobian * c / kPi + kPlaceUniform;
    for (int j = 0; j < n; ++j) density[static_cast<std::size_t>(j) * n + i] = value;
  }
  return density;
}

// Both readers need the stored floats to be what the writer warped with.
std::vector<float> as_floats(const std::vector<double>& values) { return {values.begin(), values.end()}; }
std::vector<double> as_doubles(const std::vector<float>& values) { return {values.begin(), values.end()}; }

// Isotropic: two azimuth slices, 0 and pi, both the same.
std::vector<float> twice(const std::vector<float>& v) {
  std::vector<float> both(v);
  both.insert(both.end(), v.begin(), v.end());
  return both;
}

}  // namespace

std::string rgl_file(const RglChannels& channels, const RglOptions& options, const std::string& description,
                     const std::function<void(int, int)>& progress) {
  const bool spectral = !channels.wavelengths.empty();
  const int k_channels = spectral ? static_cast<int>(channels.wavelengths.size()) : 3;
  if (static_cast<int>(channels.luminance_weights.size()) != k_channels || !channels.brdf) {
    throw std::invalid_argument("rgl_file: one luminance weight per channel, and a BRDF");
  }
  if (options.samples < RglOptions::kMinSamples || options.samples > RglOptions::kMaxSamples) {
    throw std::invalid_argument("rgl_file: samples out of range");
  }
  const double sigma = channels.top_sigma, floor = options.floor;
  const int n = options.samples, thetas = options.thetas, nv = options.vndf_size;
  const Table2 ndf_table = radial_table(options.ndf_size, [&](double t) { return ndf(std::cos(t), sigma, floor); });
  const Table2 sigma_table =
      radial_table(options.ndf_size, [&](double t) { return projected_area(std::min(t, 0.5 * kPi), sigma, floor); });
  // theta_k = (pi/4) (sin((pi/2) k / T) + k / (T - 1)), k = 0..T-1: from 0 to 89.95 degrees, about 2.5 times as
  // dense at grazing as at the normal (the BRDF changes fastest with theta_o there).
  std::vector<float> theta_nodes(static_cast<std::size_t>(thetas));
  for (int k = 0; k < thetas; ++k) {
    theta_nodes[k] = static_cast<float>(0.25 * kPi * (std::sin(0.5 * kPi * k / thetas) + k / (thetas - 1.0)));
  }
  const std::vector<float> vndf_slice = as_floats(placement(nv, sigma));
  const PiecewiseLinear2D warp(as_doubles(vndf_slice), nv, nv);
  const std::size_t plane = static_cast<std::size_t>(n) * n;
  // The nodes' half vectors and D~ there: the warp is the same for every theta_o slice.
  std::vector<Vec3> half_vectors(plane);
  std::vector<double> ndf_at(plane);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const PiecewiseLinear2D::Sample s =
          warp.sample({static_cast<double>(i) / (n - 1), static_cast<double>(j) / (n - 1)});
      const std::size_t at = static_cast<std::size_t>(j) * n + i;
      half_vectors[at] = direction_from_angles(theta_of_u(s.u[0]), phi_of_u(s.u[1]));
      ndf_at[at] = ndf_table.at(s.u[0], s.u[1]);
    }
  }
  std::vector<float> luminance(thetas * plane), values(static_cast<std::size_t>(thetas) * k_channels * plane);
  std::atomic<int> done = 0;  // slices finished, counted from the parallel-for's threads
  parallel_for_threads(thetas, [&](int k) {
    const double theta_o = theta_nodes[k];
    const Vec3 wo = direction_from_angles(theta_o, 0.0);
    const double sigma_o = sigma_table.at(u_of_theta(theta_o), 0.5);
    std::vector<double> node(static_cast<std::size_t>(k_channels));
    for (std::size_t at = 0; at < plane; ++at) {
      const Vec3& m = half_vectors[at];
      const Vec3 wi = 2.0 * wo.dot(m) * m - wo;
      std::fill(node.begin(), node.end(), 0.0);
      if (wi.z() > 0.0) {
        const double theta_i = std::acos(std::min(wi.z(), 1.0)), phi = -std::atan2(wi.y(), wi.x());
        channels.brdf(theta_i, theta_o, phi, node);
        const double scale = wi.z() * 4.0 * sigma_o / ndf_at[at];
        for (double& v : node) v *= scale;
      }
      double y = 0.0;
      for (int c = 0; c < k_channels; ++c) {
        values[(static_cast<std::size_t>(k) * k_channels + c) * plane + at] = static_cast<float>(node[c]);
        y += channels.luminance_weights[c] * node[c];
      }
      luminance[k * plane + at] = static_cast<float>(std::max(y, 0.0));
    }
    if (progress) progress(++done, thetas);
  });
  std::vector<float> vndf;
  for (int k = 0; k < thetas; ++k) vndf.insert(vndf.end(), vndf_slice.begin(), vndf_slice.end());
  const std::uint64_t t = static_cast<std::uint64_t>(thetas), un = static_cast<std::uint64_t>(n),
                      uv = static_cast<std::uint64_t>(nv), ud = static_cast<std::uint64_t>(options.ndf_size),
                      uk = static_cast<std::uint64_t>(k_channels);
  const std::vector<float> phi_nodes = {0.0f, static_cast<float>(kPi)};
  const std::vector<std::uint8_t> text(description.begin(), description.end()), jacobian = {1};
  std::vector<TensorField> fields = {
      uint8_field("description", {text.size()}, text),    uint8_field("jacobian", {1}, jacobian),
      float32_field("theta_i", {t}, theta_nodes),         float32_field("phi_i", {2}, phi_nodes),
      float32_field("ndf", {ud, ud}, ndf_table.values),   float32_field("sigma", {ud, ud}, sigma_table.values),
      float32_field("vndf", {2, t, uv, uv}, twice(vndf)), float32_field("luminance", {2, t, un, un}, twice(luminance)),
  };
  if (spectral) {
    const std::vector<float> nm(channels.wavelengths.begin(), channels.wavelengths.end());
    fields.push_back(float32_field("wavelengths", {uk}, nm));
    fields.push_back(float32_field("spectra", {2, t, uk, un, un}, twice(values)));
  } else {
    fields.push_back(float32_field("rgb", {2, t, 3, un, un}, twice(values)));
  }
  return encode_tensor_file(fields);
}

}  // namespace skinlayer
