#include "tests/app/export/rgl_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace skinlayer::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

template <typename T>
T take(const std::string& bytes, std::size_t& at) {
  if (at + sizeof(T) > bytes.size()) throw std::runtime_error("truncated header");
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

std::size_t count(const std::vector<std::uint64_t>& shape) {
  std::size_t n = 1;
  for (const std::uint64_t s : shape) n *= s;
  return n;
}

// The node at or below v (clamped to the last cell) and the linear weight toward the next one, clamped to [0, 1].
std::pair<std::size_t, double> bracket(const std::vector<float>& nodes, double v) {
  if (nodes.size() == 1) return {0, 0.0};
  std::size_t i = 0;
  while (i + 2 < nodes.size() && nodes[i + 1] <= v) ++i;
  const double w = (v - nodes[i]) / (static_cast<double>(nodes[i + 1]) - nodes[i]);
  return {i, std::clamp(w, 0.0, 1.0)};
}

// Bilinear value of one ny x nx slice (x fastest) at (ux, uy) in [0,1]^2.
double bilinear(const float* slice, std::size_t nx, std::size_t ny, double ux, double uy) {
  const double px = std::clamp(ux, 0.0, 1.0) * static_cast<double>(nx - 1);
  const double py = std::clamp(uy, 0.0, 1.0) * static_cast<double>(ny - 1);
  const std::size_t x = std::min(static_cast<std::size_t>(px), nx - 2),
                    y = std::min(static_cast<std::size_t>(py), ny - 2);
  const double a = px - static_cast<double>(x), b = py - static_cast<double>(y);
  const auto v = [&](std::size_t i, std::size_t j) { return static_cast<double>(slice[j * nx + i]); };
  return (1 - b) * ((1 - a) * v(x, y) + a * v(x + 1, y)) + b * ((1 - a) * v(x, y + 1) + a * v(x + 1, y + 1));
}

// The inverse of the VNDF's sampling warp at u_m, for the slices around (phi_o, theta_o): each slice normalized to a
// density on the unit square with its row and marginal CDFs, the neighbouring slices blended linearly.
std::array<double, 2> invert_vndf(const RglFile& file, double phi_o, double theta_o, double ux, double uy) {
  const RglField& vndf = file.at("vndf");
  const std::size_t p = vndf.shape[0], t = vndf.shape[1], ny = vndf.shape[2], nx = vndf.shape[3];
  const auto [pi, pw] = bracket(file.at("phi_i").floats, phi_o);
  const auto [ti, tw] = bracket(file.at("theta_i").floats, theta_o);
  // Per neighbouring slice: its normalized data, row CDFs and marginal; then the weighted sums.
  std::vector<double> data(nx * ny, 0.0), rows(nx * ny, 0.0), marginal(ny, 0.0);
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b) {
      const double w = (a ? pw : 1 - pw) * (b ? tw : 1 - tw);
      const std::size_t ps = std::min(pi + a, p - 1), ts = std::min(ti + b, t - 1);
      if (w == 0.0) continue;
      const float* d = vndf.floats.data() + (ps * t + ts) * nx * ny;
      std::vector<double> c(nx * ny, 0.0), m(ny, 0.0);
      for (std::size_t y = 0; y < ny; ++y) {
        for (std::size_t x = 1; x < nx; ++x) {
          c[y * nx + x] = c[y * nx + x - 1] + 0.5 * (static_cast<double>(d[y * nx + x - 1]) + d[y * nx + x]);
        }
      }
      for (std::size_t y = 1; y < ny; ++y) m[y] = m[y - 1] + 0.5 * (c[y * nx - 1] + c[(y + 1) * nx - 1]);
      const double total = m[ny - 1];
      for (std::size_t i = 0; i < nx * ny; ++i) {
        data[i] += w * d[i] / total;
        rows[i] += w * c[i] / total;
      }
      for (std::size_t y = 0; y < ny; ++y) marginal[y] += w * m[y] / total;
    }
  }
  const double px = std::clamp(ux, 0.0, 1.0) * static_cast<double>(nx - 1);
  const double py = std::clamp(uy, 0.0, 1.0) * static_cast<double>(ny - 1);
  const std::size_t x = std::min(static_cast<std::size_t>(px), nx - 2),
                    y = std::min(static_cast<std::size_t>(py), ny - 2);
  const double s = px - static_cast<double>(x), r = py - static_cast<double>(y);
  const std::size_t i0 = y * nx + x, i1 = i0 + nx;
  const double c0 = (1 - r) * data[i0] + r * data[i1], c1 = (1 - r) * data[i0 + 1] + r * data[i1 + 1];
  // Within the cell the density in x runs linearly from c0 to c1: its integral up to s is s (c0 + s (c1 - c0) / 2).
  double xi_x = s * (c0 + 0.5 * s * (c1 - c0)) + (1 - r) * rows[i0] + r * rows[i1];
  const double row0 = rows[(y + 1) * nx - 1], row1 = rows[(y + 2) * nx - 1];
  xi_x /= (1 - r) * row0 + r * row1;
  const double xi_y = r * (row0 + 0.5 * r * (row1 - row0)) + marginal[y];
  return {xi_x, xi_y};
}

}  // namespace

const RglField& RglFile::at(const std::string& name) const {
  const auto found = fields.find(name);
  if (found == fields.end()) throw std::runtime_error("no field " + name);
  return found->second;
}

RglFile read_rgl(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 18 || std::memcmp(bytes.data(), "tensor_file\0", 12) != 0) throw std::runtime_error("bad magic");
  if (bytes[12] != 1 || bytes[13] != 0) throw std::runtime_error("bad version");
  std::size_t at = 14;
  const std::uint32_t fields = take<std::uint32_t>(bytes, at);
  RglFile file;
  for (std::uint32_t f = 0; f < fields; ++f) {
    const std::uint16_t length = take<std::uint16_t>(bytes, at);
    if (at + length > bytes.size()) throw std::runtime_error("truncated name");
    const std::string name = bytes.substr(at, length);
    at += length;
    const std::uint16_t rank = take<std::uint16_t>(bytes, at);
    RglField field;
    field.dtype = take<std::uint8_t>(bytes, at);
    const std::uint64_t offset = take<std::uint64_t>(bytes, at);
    for (std::uint16_t r = 0; r < rank; ++r) field.shape.push_back(take<std::uint64_t>(bytes, at));
    if (field.dtype != 1 && field.dtype != 10)
      throw std::runtime_error(name + ": dtype " + std::to_string(field.dtype));
    if (offset % 8 != 0) throw std::runtime_error(name + ": offset not 8-byte aligned");
    const std::size_t size = count(field.shape) * (field.dtype == 10 ? 4 : 1);
    if (offset + size > bytes.size()) throw std::runtime_error(name + ": data runs past the end");
    if (field.dtype == 10) {
      field.floats.resize(count(field.shape));
      std::memcpy(field.floats.data(), bytes.data() + offset, size);
    } else {
      field.bytes.assign(bytes.begin() + static_cast<std::ptrdiff_t>(offset),
                         bytes.begin() + static_cast<std::ptrdiff_t>(offset + size));
    }
    if (!file.fields.emplace(name, std::move(field)).second) throw std::runtime_error("repeated field " + name);
  }
  // The BSDF's fields and their shapes.
  const std::size_t t = file.at("theta_i").floats.size(), p = file.at("phi_i").floats.size();
  const RglField& vndf = file.at("vndf");
  const RglField& rgb = file.at("rgb");
  const RglField& luminance = file.at("luminance");
  const bool shapes = file.at("ndf").shape.size() == 2 && file.at("sigma").shape.size() == 2 &&
                      vndf.shape.size() == 4 && vndf.shape[0] == p && vndf.shape[1] == t && rgb.shape.size() == 5 &&
                      rgb.shape[0] == p && rgb.shape[1] == t && rgb.shape[2] == 3 && luminance.shape.size() == 4 &&
                      luminance.shape[2] == rgb.shape[3] && luminance.shape[3] == rgb.shape[4] &&
                      file.at("jacobian").bytes.size() == 1 && file.at("description").dtype == 1;
  if (!shapes) throw std::runtime_error("misshapen BSDF fields");
  return file;
}

std::array<double, 3> rgl_brdf(const RglFile& file, const std::array<double, 3>& wo, const std::array<double, 3>& wi) {
  if (wo[2] <= 0.0 || wi[2] <= 0.0) return {0.0, 0.0, 0.0};
  std::array<double, 3> m = {wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2]};
  const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  for (double& c : m) c /= length;
  const double theta_o = std::acos(std::clamp(wo[2], -1.0, 1.0)), phi_o = std::atan2(wo[1], wo[0]);
  const double theta_m = std::acos(std::clamp(m[2], -1.0, 1.0)), phi_m = std::atan2(m[1], m[0]);
  const auto u_theta = [](double theta) { return std::sqrt(2.0 * theta / kPi); };
  const auto u_phi = [](double phi) { return (phi + kPi) / (2.0 * kPi); };
  double um_y = u_phi(phi_m - phi_o);  // isotropic: the half vector's azimuth from the camera's
  um_y -= std::floor(um_y);
  const double um_x = u_theta(theta_m);
  const std::array<double, 2> xi = invert_vndf(file, phi_o, theta_o, um_x, um_y);
  const RglField& ndf = file.at("ndf");
  const RglField& sigma = file.at("sigma");
  const double d = bilinear(ndf.floats.data(), ndf.shape[1], ndf.shape[0], um_x, um_y);
  const double s = bilinear(sigma.floats.data(), sigma.shape[1], sigma.shape[0], u_theta(theta_o), u_phi(phi_o));
  const RglField& rgb = file.at("rgb");
  const std::size_t p = rgb.shape[0], t = rgb.shape[1], n_y = rgb.shape[3], n_x = rgb.shape[4];
  const auto [pi, pw] = bracket(file.at("phi_i").floats, phi_o);
  const auto [ti, tw] = bracket(file.at("theta_i").floats, theta_o);
  std::array<double, 3> f{};
  for (std::size_t c = 0; c < 3; ++c) {
    double value = 0.0;
    for (int a = 0; a < 2; ++a) {
      for (int b = 0; b < 2; ++b) {
        const double w = (a ? pw : 1 - pw) * (b ? tw : 1 - tw);
        if (w == 0.0) continue;
        const std::size_t ps = std::min(pi + a, p - 1), ts = std::min(ti + b, t - 1);
        value += w * bilinear(rgb.floats.data() + ((ps * t + ts) * 3 + c) * n_x * n_y, n_x, n_y, xi[0], xi[1]);
      }
    }
    f[c] = std::max(0.0, value) * d / (4.0 * s * wi[2]);
  }
  return f;
}

}  // namespace skinlayer::test
