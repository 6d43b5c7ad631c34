#include "app/export/rgl_export.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
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

Vec3 direction(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// sigma(theta) = int D(m) max(0, w . m) dm for w at polar angle theta: the NDF's projected area toward w.
double projected_area(double theta, double sigma, double floor) {
  const QuadratureRule polar = gauss_legendre(256, 0.0, 0.5 * kPi);
  constexpr int kAzimuths = 128;
  const Vec3 w = direction(theta, 0.0);
  double sum = 0.0;
  for (int a = 0; a < polar.size(); ++a) {
    const double t = polar.nodes[a], d = ndf(std::cos(t), sigma, floor);
    double ring = 0.0;
    for (int k = 0; k < kAzimuths; ++k) ring += std::max(0.0, w.dot(direction(t, 2.0 * kPi * (k + 0.5) / kAzimuths)));
    sum += polar.weights[a] * std::sin(t) * d * ring * (2.0 * kPi / kAzimuths);
  }
  return sum;
}

}  // namespace

std::string rgl_rgb_file(const ColorTables& tables, const RglOptions& options, const std::string& description,
                         const std::function<void(int, int)>& progress) {
  const double sigma = tables.material.layer.sigma, floor = options.floor;
  const int nd = options.ndf_size, n = options.samples, thetas = options.thetas;
  Table2 ndf_table{nd, nd, std::vector<float>(static_cast<std::size_t>(nd) * nd)};
  Table2 sigma_table{nd, nd, std::vector<float>(static_cast<std::size_t>(nd) * nd)};
  for (int i = 0; i < nd; ++i) {
    const double theta = theta_of_u(static_cast<double>(i) / (nd - 1));
    const float d = static_cast<float>(ndf(std::cos(theta), sigma, floor));
    const float s = static_cast<float>(projected_area(std::min(theta, 0.5 * kPi), sigma, floor));
    for (int j = 0; j < nd; ++j) {
      ndf_table.values[static_cast<std::size_t>(j) * nd + i] = d;
      sigma_table.values[static_cast<std::size_t>(j) * nd + i] = s;
    }
  }
  std::vector<float> theta_nodes(static_cast<std::size_t>(thetas));
  // Denser toward grazing, where the VNDF changes fastest with theta_o:
  // theta_k = (pi/2) sin((pi/2) k / T), k = 0..T-1 (the last at 89.9 degrees for T = 32).
  for (int k = 0; k < thetas; ++k) theta_nodes[k] = static_cast<float>(0.5 * kPi * std::sin(0.5 * kPi * k / thetas));
  const std::size_t vndf_slice = static_cast<std::size_t>(nd) * nd, sample_slice = static_cast<std::size_t>(n) * n;
  std::vector<float> vndf(thetas * vndf_slice), luminance(thetas * sample_slice), rgb(thetas * 3 * sample_slice);
  std::atomic<int> done = 0;  // slices finished, counted from the parallel-for's threads
  parallel_for_threads(thetas, [&](int k) {
    const double theta_o = theta_nodes[k];
    const Vec3 wo = direction(theta_o, 0.0);
    std::vector<double> slice(vndf_slice);
    for (int j = 0; j < nd; ++j) {    // y: u(phi_m - phi_o)
      for (int i = 0; i < nd; ++i) {  // x: u(theta_m)
        const double u = static_cast<double>(i) / (nd - 1), theta_m = theta_of_u(u);
        const Vec3 m = direction(theta_m, phi_of_u(static_cast<double>(j) / (nd - 1)));
        const float value = static_cast<float>(2.0 * kPi * kPi * u * std::sin(theta_m) * std::max(0.0, wo.dot(m)) *
                                               ndf(std::cos(theta_m), sigma, floor));
        vndf[k * vndf_slice + static_cast<std::size_t>(j) * nd + i] = value;
        slice[static_cast<std::size_t>(j) * nd + i] = value;  // the readers warp with the stored floats
      }
    }
    const PiecewiseLinear2D warp(slice, nd, nd);
    const double sigma_o = sigma_table.at(u_of_theta(theta_o), 0.5);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const PiecewiseLinear2D::Sample s =
            warp.sample({static_cast<double>(i) / (n - 1), static_cast<double>(j) / (n - 1)});
        const Vec3 m = direction(theta_of_u(s.u[0]), phi_of_u(s.u[1]));
        const Vec3 wi = 2.0 * wo.dot(m) * m - wo;
        std::array<double, 3> value{};
        if (wi.z() > 0.0) {
          const double theta_i = std::acos(std::min(wi.z(), 1.0)), phi = -std::atan2(wi.y(), wi.x());
          const double scale = wi.z() * 4.0 * sigma_o / ndf_table.at(s.u[0], s.u[1]);
          for (int c = 0; c < 3; ++c) value[c] = brdf_total(tables, c, theta_i, theta_o, phi) * scale;
        }
        const std::size_t node = static_cast<std::size_t>(j) * n + i;
        for (int c = 0; c < 3; ++c) rgb[(k * 3 + c) * sample_slice + node] = static_cast<float>(value[c]);
        luminance[k * sample_slice + node] =
            static_cast<float>(0.2126 * value[0] + 0.7152 * value[1] + 0.0722 * value[2]);
      }
    }
    if (progress) progress(++done, thetas);
  });
  // Isotropic: two azimuth slices, 0 and pi, both the same.
  const auto twice = [](const std::vector<float>& v) {
    std::vector<float> both(v);
    both.insert(both.end(), v.begin(), v.end());
    return both;
  };
  const std::uint64_t t = static_cast<std::uint64_t>(thetas), un = static_cast<std::uint64_t>(n),
                      ud = static_cast<std::uint64_t>(nd);
  const std::vector<float> phi_nodes = {0.0f, static_cast<float>(kPi)};
  const std::vector<std::uint8_t> text(description.begin(), description.end()), jacobian = {1};
  const std::vector<TensorField> fields = {
      uint8_field("description", {text.size()}, text),     uint8_field("jacobian", {1}, jacobian),
      float32_field("theta_i", {t}, theta_nodes),          float32_field("phi_i", {2}, phi_nodes),
      float32_field("ndf", {ud, ud}, ndf_table.values),    float32_field("sigma", {ud, ud}, sigma_table.values),
      float32_field("vndf", {2, t, ud, ud}, twice(vndf)),  float32_field("luminance", {2, t, un, un}, twice(luminance)),
      float32_field("rgb", {2, t, 3, un, un}, twice(rgb)),
  };
  return encode_tensor_file(fields);
}

}  // namespace skinlayer
