#include "tests/app/export/rgl_reader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
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
template <typename T>
double bilinear(const T* slice, std::size_t nx, std::size_t ny, double ux, double uy) {
  const double px = std::clamp(ux, 0.0, 1.0) * static_cast<double>(nx - 1);
  const double py = std::clamp(uy, 0.0, 1.0) * static_cast<double>(ny - 1);
  const std::size_t x = std::min(static_cast<std::size_t>(px), nx - 2),
                    y = std::min(static_cast<std::size_t>(py), ny - 2);
  const double a = px - static_cast<double>(x), b = py - static_cast<double>(y);
  const auto v = [&](std::size_t i, std::size_t j) { return static_cast<double>(slice[j * nx + i]); };
  return (1 - b) * ((1 - a) * v(x, y) + a * v(x + 1, y)) + b * ((1 - a) * v(x, y + 1) + a * v(x + 1, y + 1));
}

// The slices of a warp's field (vndf, luminance) around the parameters (phi_o, theta_o), each ny x nx (x fastest),
// each divided by its integral over the square (trapezoids in grid units, a cell 1 x 1) with its row and marginal
// CDFs, then blended linearly as both readers blend them.
struct Blended {
  std::size_t nx = 0, ny = 0;
  std::vector<double> data, rows, marginal;

  double bilinear_at(double ux, double uy) const { return bilinear(data.data(), nx, ny, ux, uy); }
  // The density on the unit square (normalized slices only).
  double density(double ux, double uy) const { return static_cast<double>((nx - 1) * (ny - 1)) * bilinear_at(ux, uy); }
  double row_total(std::size_t y) const { return rows[y * nx + nx - 1]; }
  // The warp's inverse at u: the xi it comes from, and the density there.
  std::pair<std::array<double, 2>, double> invert(double ux, double uy) const {
    const double px = std::clamp(ux, 0.0, 1.0) * static_cast<double>(nx - 1);
    const double py = std::clamp(uy, 0.0, 1.0) * static_cast<double>(ny - 1);
    const std::size_t x = std::min(static_cast<std::size_t>(px), nx - 2),
                      y = std::min(static_cast<std::size_t>(py), ny - 2);
    const double s = px - static_cast<double>(x), r = py - static_cast<double>(y);
    const std::size_t i0 = y * nx + x, i1 = i0 + nx;
    const double c0 = (1 - r) * data[i0] + r * data[i1], c1 = (1 - r) * data[i0 + 1] + r * data[i1 + 1];
    // Within the cell the density in x runs linearly from c0 to c1: its integral up to s is s (c0 + s (c1 - c0) / 2).
    double xi_x = s * (c0 + 0.5 * s * (c1 - c0)) + (1 - r) * rows[i0] + r * rows[i1];
    const double row0 = row_total(y), row1 = row_total(y + 1);
    xi_x /= (1 - r) * row0 + r * row1;
    const double xi_y = r * (row0 + 0.5 * r * (row1 - row0)) + marginal[y];
    return {{xi_x, xi_y}, density(ux, uy)};
  }
  // The warp: xi to u, through the marginal in y and then the conditional in x, each inverted within its cell.
  std::pair<std::array<double, 2>, double> sample(double xi_x, double xi_y) const {
    // t in [0, 1] with start + t (a + t (b - a) / 2) = target: the integral of a density linear from a to b.
    const auto within = [](double start, double a, double b, double target) {
      const double c = start - target, half = 0.5 * (b - a);
      const double root = std::sqrt(std::max(a * a - 4.0 * half * c, 0.0));
      return a + root > 0.0 ? std::clamp(-2.0 * c / (a + root), 0.0, 1.0) : 0.0;
    };
    std::size_t y = 0;
    while (y + 2 < ny && marginal[y + 1] <= xi_y) ++y;
    const double r = within(marginal[y], row_total(y), row_total(y + 1), xi_y);
    const double target = xi_x * ((1 - r) * row_total(y) + r * row_total(y + 1));
    const auto conditional = [&](std::size_t x) { return (1 - r) * rows[y * nx + x] + r * rows[(y + 1) * nx + x]; };
    std::size_t x = 0;
    while (x + 2 < nx && conditional(x + 1) <= target) ++x;
    const double c0 = (1 - r) * data[y * nx + x] + r * data[(y + 1) * nx + x];
    const double c1 = (1 - r) * data[y * nx + x + 1] + r * data[(y + 1) * nx + x + 1];
    const double s = within(conditional(x), c0, c1, target);
    const double ux = (static_cast<double>(x) + s) / static_cast<double>(nx - 1),
                 uy = (static_cast<double>(y) + r) / static_cast<double>(ny - 1);
    return {{ux, uy}, density(ux, uy)};
  }
};

// A field of shape [phi, theta, ny, nx] blended at (phi_o, theta_o), each slice normalized first.
Blended blend(const RglFile& file, const std::string& name, double phi_o, double theta_o) {
  const RglField& field = file.at(name);
  const std::size_t p = field.shape[0], t = field.shape[1];
  Blended b;
  b.ny = field.shape[2];
  b.nx = field.shape[3];
  const std::size_t plane = b.nx * b.ny;
  b.data.assign(plane, 0.0);
  b.rows.assign(plane, 0.0);
  b.marginal.assign(b.ny, 0.0);
  const auto [pi, pw] = bracket(file.at("phi_i").floats, phi_o);
  const auto [ti, tw] = bracket(file.at("theta_i").floats, theta_o);
  for (int a = 0; a < 2; ++a) {
    for (int c = 0; c < 2; ++c) {
      const double w = (a ? pw : 1 - pw) * (c ? tw : 1 - tw);
      if (w == 0.0) continue;
      const std::size_t ps = std::min(pi + a, p - 1), ts = std::min(ti + c, t - 1);
      const float* d = field.floats.data() + (ps * t + ts) * plane;
      std::vector<double> cdf(plane, 0.0), m(b.ny, 0.0);
      for (std::size_t y = 0; y < b.ny; ++y) {
        for (std::size_t x = 1; x < b.nx; ++x) {
          cdf[y * b.nx + x] =
              cdf[y * b.nx + x - 1] + 0.5 * (static_cast<double>(d[y * b.nx + x - 1]) + d[y * b.nx + x]);
        }
      }
      for (std::size_t y = 1; y < b.ny; ++y) m[y] = m[y - 1] + 0.5 * (cdf[y * b.nx - 1] + cdf[(y + 1) * b.nx - 1]);
      const double total = m[b.ny - 1];
      for (std::size_t i = 0; i < plane; ++i) {
        b.data[i] += w * d[i] / total;
        b.rows[i] += w * cdf[i] / total;
      }
      for (std::size_t y = 0; y < b.ny; ++y) b.marginal[y] += w * m[y] / total;
    }
  }
  return b;
}

// A raw field of shape [phi, theta, k, ny, nx] at (phi_o, theta_o), the k-parameter and xi: the blend of the
// neighbouring slices' bilinear values.
double value_at(const RglFile& file, const std::string& name, double phi_o, double theta_o,
                const std::vector<float>& k_nodes, double k_value, const std::array<double, 2>& xi) {
  const RglField& field = file.at(name);
  const std::size_t p = field.shape[0], t = field.shape[1], k = field.shape[2], ny = field.shape[3],
                    nx = field.shape[4];
  const auto [pi, pw] = bracket(file.at("phi_i").floats, phi_o);
  const auto [ti, tw] = bracket(file.at("theta_i").floats, theta_o);
  const auto [ki, kw] = bracket(k_nodes, k_value);
  double value = 0.0;
  for (int a = 0; a < 2; ++a) {
    for (int c = 0; c < 2; ++c) {
      for (int e = 0; e < 2; ++e) {
        const double w = (a ? pw : 1 - pw) * (c ? tw : 1 - tw) * (e ? kw : 1 - kw);
        if (w == 0.0) continue;
        const std::size_t ps = std::min(pi + a, p - 1), ts = std::min(ti + c, t - 1), ks = std::min(ki + e, k - 1);
        value += w * bilinear(field.floats.data() + ((ps * t + ts) * k + ks) * nx * ny, nx, ny, xi[0], xi[1]);
      }
    }
  }
  return value;
}

double u_theta(double theta) { return std::sqrt(2.0 * theta / kPi); }
double u_phi(double phi) { return (phi + kPi) / (2.0 * kPi); }

}  // namespace

struct RglCamera::Tables {
  double theta_o = 0.0, phi_o = 0.0, sigma_o = 0.0;
  Blended vndf, luminance;
};

RglCamera::RglCamera(const RglFile& file, const Direction& wo)
    : file_(file), wo_(wo), tables_(std::make_unique<Tables>()) {
  tables_->theta_o = std::acos(std::clamp(wo[2], -1.0, 1.0));
  tables_->phi_o = std::atan2(wo[1], wo[0]);
  tables_->vndf = blend(file, "vndf", tables_->phi_o, tables_->theta_o);
  tables_->luminance = blend(file, "luminance", tables_->phi_o, tables_->theta_o);
  const RglField& sigma = file.at("sigma");
  tables_->sigma_o =
      bilinear(sigma.floats.data(), sigma.shape[1], sigma.shape[0], u_theta(tables_->theta_o), u_phi(tables_->phi_o));
}

RglCamera::~RglCamera() = default;

namespace {

// What every reading of a pair needs: the half vector's point u_m on the square, its xi and the VNDF density there,
// and D~(u_m) / (4 sigma~(u_o)).
struct Lookup {
  std::array<double, 2> u_m{}, xi{};
  double vndf_pdf = 0.0, jacobian_factor = 0.0, sin_theta_m = 0.0, wo_dot_m = 0.0;
};

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
  const RglField& luminance = file.at("luminance");
  const bool spectral = file.spectral();
  const RglField& values = file.at(spectral ? "spectra" : "rgb");
  const std::size_t channels = spectral ? file.at("wavelengths").floats.size() : 3;
  if (spectral && file.fields.contains("rgb")) throw std::runtime_error("both rgb and spectra");
  const bool shapes = file.at("ndf").shape.size() == 2 && file.at("sigma").shape.size() == 2 &&
                      vndf.shape.size() == 4 && vndf.shape[0] == p && vndf.shape[1] == t && values.shape.size() == 5 &&
                      values.shape[0] == p && values.shape[1] == t && values.shape[2] == channels &&
                      luminance.shape.size() == 4 && luminance.shape[0] == p && luminance.shape[1] == t &&
                      luminance.shape[2] == values.shape[3] && luminance.shape[3] == values.shape[4] &&
                      file.at("jacobian").bytes.size() == 1 && file.at("description").dtype == 1 && p >= 2 && t >= 2;
  if (!shapes) throw std::runtime_error("misshapen BSDF fields");
  return file;
}

namespace {

std::optional<Lookup> look_up(const RglFile& file, const Blended& vndf, double phi_o, const Direction& wo,
                              const Direction& wi, double sigma_o) {
  if (wo[2] <= 0.0 || wi[2] <= 0.0) return std::nullopt;
  std::array<double, 3> m = {wo[0] + wi[0], wo[1] + wi[1], wo[2] + wi[2]};
  const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  if (length == 0.0) return std::nullopt;
  for (double& c : m) c /= length;
  Lookup l;
  const double theta_m = std::acos(std::clamp(m[2], -1.0, 1.0)), phi_m = std::atan2(m[1], m[0]);
  double um_y = u_phi(phi_m - phi_o);  // isotropic: the half vector's azimuth from the camera's
  um_y -= std::floor(um_y);
  l.u_m = {u_theta(theta_m), um_y};
  const auto [xi, pdf] = vndf.invert(l.u_m[0], l.u_m[1]);
  l.xi = xi;
  l.vndf_pdf = pdf;
  const RglField& ndf = file.at("ndf");
  l.jacobian_factor = bilinear(ndf.floats.data(), ndf.shape[1], ndf.shape[0], l.u_m[0], l.u_m[1]) / (4.0 * sigma_o);
  l.sin_theta_m = std::sqrt(m[0] * m[0] + m[1] * m[1]);
  l.wo_dot_m = wo[0] * m[0] + wo[1] * m[1] + wo[2] * m[2];
  return l;
}

// S at xi: the rgb channel, or the spectrum at a wavelength.
double stored_value(const RglFile& file, double phi_o, double theta_o, const Lookup& l, const RglChannel& channel) {
  if (file.spectral()) {
    return value_at(file, "spectra", phi_o, theta_o, file.at("wavelengths").floats, channel.wavelength_nm, l.xi);
  }
  const std::vector<float> channels = {0.0f, 1.0f, 2.0f};
  return value_at(file, "rgb", phi_o, theta_o, channels, channel.rgb, l.xi);
}

}  // namespace

double RglCamera::brdf(const Direction& wi, const RglChannel& channel) const {
  const std::optional<Lookup> l = look_up(file_, tables_->vndf, tables_->phi_o, wo_, wi, tables_->sigma_o);
  if (!l) return 0.0;
  return std::max(0.0, stored_value(file_, tables_->phi_o, tables_->theta_o, *l, channel)) * l->jacobian_factor / wi[2];
}

double RglCamera::brdf_mitsuba(const Direction& wi, const RglChannel& channel) const {
  const std::optional<Lookup> l = look_up(file_, tables_->vndf, tables_->phi_o, wo_, wi, tables_->sigma_o);
  if (!l) return 0.0;
  const double factor = file_.at("jacobian").bytes.at(0) ? l->jacobian_factor : 1.0;
  return stored_value(file_, tables_->phi_o, tables_->theta_o, *l, channel) * factor / wi[2];
}

double RglCamera::pdf(const Direction& wi) const {
  const std::optional<Lookup> l = look_up(file_, tables_->vndf, tables_->phi_o, wo_, wi, tables_->sigma_o);
  if (!l) return 0.0;
  const double luminance = tables_->luminance.density(l->xi[0], l->xi[1]);
  const double jacobian = 4.0 * l->wo_dot_m * std::max(2.0 * kPi * kPi * l->u_m[0] * l->sin_theta_m, 1e-6);
  return l->vndf_pdf * luminance / jacobian;
}

std::optional<RglCamera::Sample> RglCamera::sample(double u1, double u2) const {
  if (wo_[2] <= 0.0) return std::nullopt;
  const auto [xi, luminance_pdf] = tables_->luminance.sample(u1, u2);
  const auto [u_m, vndf_pdf] = tables_->vndf.sample(xi[0], xi[1]);
  const double theta_m = 0.5 * kPi * u_m[0] * u_m[0], phi_m = 2.0 * kPi * u_m[1] - kPi + tables_->phi_o;
  const Direction m = {std::sin(theta_m) * std::cos(phi_m), std::sin(theta_m) * std::sin(phi_m), std::cos(theta_m)};
  const double dot = wo_[0] * m[0] + wo_[1] * m[1] + wo_[2] * m[2];
  const Direction wi = {2.0 * dot * m[0] - wo_[0], 2.0 * dot * m[1] - wo_[1], 2.0 * dot * m[2] - wo_[2]};
  if (wi[2] <= 0.0) return std::nullopt;
  const double jacobian = 4.0 * dot * std::max(2.0 * kPi * kPi * u_m[0] * std::sin(theta_m), 1e-6);
  return Sample{wi, vndf_pdf * luminance_pdf / jacobian};
}

std::array<double, 3> rgl_brdf_rgb(const RglFile& file, const Direction& wo, const Direction& wi) {
  const RglCamera camera(file, wo);
  return {camera.brdf(wi, {0}), camera.brdf(wi, {1}), camera.brdf(wi, {2})};
}

}  // namespace skinlayer::test
