#include "app/render/environment_map.h"

#include <stb_image.h>  // libstb.so holds the implementation

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <iterator>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "app/render/radiance_hdr_scan.h"
#include "core/color/luminance.h"

namespace skinlayer {

namespace {

constexpr double kPi = std::numbers::pi;

// The luminance of a texel's linear RGB (core/color/luminance.h).
double texel_luminance(const float* rgb) { return luminance(rgb[0], rgb[1], rgb[2]); }

// A map whose texel values are radiance(direction at the texel centre).
template <class Radiance>
EnvironmentMap procedural(int width, int height, const Radiance& radiance) {
  EnvironmentMap map{width, height, std::vector<float>(static_cast<std::size_t>(width) * height * 3)};
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const glm::dvec3 rgb = radiance(environment_direction((i + 0.5) / width, (j + 0.5) / height));
      for (int c = 0; c < 3; ++c)
        map.rgb[(static_cast<std::size_t>(j) * width + i) * 3 + c] = static_cast<float>(rgb[c]);
    }
  }
  return map;
}

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// A soft-edged rectangle light facing the origin: centred on the unit direction `centre`, `half_width` wide along
// `across` (perpendicular to it) and `half_height` along their cross product, in units of its distance, its edges
// falling off over `soft`. 1 inside, 0 outside.
double rectangle_light(const glm::dvec3& d, const glm::dvec3& centre, const glm::dvec3& across, double half_width,
                       double half_height, double soft) {
  const double t = glm::dot(d, centre);
  if (t <= 0.1) return 0.0;
  const glm::dvec3 up = glm::cross(centre, across);
  const double a = glm::dot(d, across) / t;
  const double b = glm::dot(d, up) / t;
  return (1.0 - smoothstep(half_width, half_width + soft, std::abs(a))) *
         (1.0 - smoothstep(half_height, half_height + soft, std::abs(b)));
}

EnvironmentMap studio() {
  // The key: a 1.2 x 0.9 softbox above and in front of the sphere (55 degrees up, toward the camera), radiance 5;
  // two strip lights 0.25 x 1.8 at the sides, a little behind (rim lights), radiance 4; over a dim gradient from
  // 0.03 at the floor to 0.15 overhead.
  const glm::dvec3 key = glm::normalize(glm::dvec3(0.0, 1.4, 1.0));
  const glm::dvec3 left = glm::normalize(glm::dvec3(-1.0, 0.0, -0.4));
  const glm::dvec3 right = glm::normalize(glm::dvec3(1.0, 0.0, -0.4));
  return procedural(512, 256, [&](const glm::dvec3& d) {
    const double base = 0.03 + 0.12 * smoothstep(-1.0, 1.0, d.y);
    const double light = 5.0 * rectangle_light(d, key, glm::dvec3(1.0, 0.0, 0.0), 0.6, 0.45, 0.05) +
                         4.0 * rectangle_light(d, left, glm::normalize(glm::dvec3(0.4, 0.0, -1.0)), 0.125, 0.9, 0.03) +
                         4.0 * rectangle_light(d, right, glm::normalize(glm::dvec3(0.4, 0.0, 1.0)), 0.125, 0.9, 0.03);
    const double total = base + light;
    return glm::dvec3(total, total, total * 1.02);
  });
}

EnvironmentMap sky() {
  // The sun 35 degrees above the horizon, to the upper left and slightly behind the sphere: a disk 1.5 degrees in
  // radius (wider than the real sun's 0.27, so that a 1024 x 512 map holds it in some 40 texels).
  const double elevation = 35.0 * kPi / 180.0, azimuth = -2.2;
  const glm::dvec3 sun(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                       std::cos(elevation) * std::cos(azimuth));
  return procedural(1024, 512, [sun](const glm::dvec3& d) {
    const double up = d.y;
    const double cos_sun = glm::dot(d, sun);
    glm::dvec3 rgb;
    if (up >= 0.0) {  // the sky: deep blue overhead, pale at the horizon, brighter around the sun
      const double h = std::pow(1.0 - up, 3.0);
      const double glow = 0.6 * std::pow(std::max(0.0, cos_sun), 32.0);
      rgb = glm::dvec3(0.18 + 0.5 * h + glow, 0.32 + 0.45 * h + glow * 0.9, 0.7 + 0.25 * h + glow * 0.7);
    } else {  // the ground: a warm grey, darker straight down
      const double g = 0.12 + 0.08 * (1.0 + up);
      rgb = glm::dvec3(g * 1.05, g, g * 0.9);
    }
    // The sun's disk: radiance 1400 over 2.15e-3 sr, an irradiance of about 3 (a white Lambertian plane under it: 1).
    if (cos_sun > std::cos(1.5 * kPi / 180.0)) rgb = glm::dvec3(1400.0, 1350.0, 1250.0);
    return rgb;
  });
}

}  // namespace

glm::dvec3 environment_direction(double u, double v) {
  const double theta = kPi * v, phi = 2.0 * kPi * u;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
}

glm::dvec2 environment_coordinates(const glm::dvec3& d) {
  double u = std::atan2(d.x, d.z) / (2.0 * kPi);
  if (u < 0.0) u += 1.0;
  return {u, std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi};
}

glm::dmat3 environment_from_world(double alpha) {
  return glm::dmat3(glm::rotate(glm::dmat4(1.0), -alpha, glm::dvec3(0.0, 1.0, 0.0)));
}

std::optional<EnvironmentMap> builtin_environment(std::string_view name) {
  if (name == "furnace") return EnvironmentMap{64, 32, std::vector<float>(64 * 32 * 3, 1.0f)};
  if (name == "studio") return studio();
  if (name == "sky") return sky();
  return std::nullopt;
}

EnvironmentMap decode_hdr_environment(std::string_view bytes, std::string_view source) {
  const std::string name(source);
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::runtime_error("cannot read " + name + " as an environment: larger than 2 GB");
  }
  const int size = static_cast<int>(bytes.size());
  if (!stbi_is_hdr_from_memory(data, size)) {
    throw std::runtime_error("cannot read " + name + " as an environment: not a Radiance .hdr image");
  }
  // The header's size is checked before any pixel is read, so that a few bytes cannot ask for gigabytes.
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(data, size, &width, &height, &channels)) {
    const char* reason = stbi_failure_reason();
    throw std::runtime_error("cannot read " + name + ": " + (reason ? reason : "a damaged .hdr header"));
  }
  if (width < 1 || height < 1) {
    throw std::runtime_error("cannot use " + name + " as an environment: it has no pixels (" + std::to_string(width) +
                             "x" + std::to_string(height) + ")");
  }
  if (width > kMaxEnvironmentWidth || height > kMaxEnvironmentWidth / 2) {
    throw std::runtime_error("cannot use " + name + " as an environment: " + std::to_string(width) + "x" +
                             std::to_string(height) + " is larger than " + std::to_string(kMaxEnvironmentWidth) + "x" +
                             std::to_string(kMaxEnvironmentWidth / 2));
  }
  if (std::abs(width - 2 * height) > 1) {
    throw std::runtime_error("cannot use " + name + " as an environment: " + std::to_string(width) + "x" +
                             std::to_string(height) + " is not equirectangular (width must be twice the height)");
  }
  // Walked first: stb_image can hang on damaged run-length data, and reads zeros past the end.
  if (const std::optional<std::string> problem = radiance_pixel_data_problem(bytes, width, height)) {
    throw std::runtime_error("cannot read " + name + ": " + *problem);
  }
  const std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_memory(data, size, &width, &height, &channels, 3), stbi_image_free);
  if (!pixels) {
    const char* reason = stbi_failure_reason();
    throw std::runtime_error("cannot read " + name + ": " + (reason ? reason : "stb_image failed"));
  }
  EnvironmentMap map{width, height, std::vector<float>(pixels.get(), pixels.get() + std::size_t{3} * width * height)};
  for (float& value : map.rgb) {
    if (!std::isfinite(value) || value < 0.0f) value = 0.0f;
  }
  return map;
}

EnvironmentMap read_hdr_environment(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  return decode_hdr_environment(bytes, path);
}

EnvironmentMap load_environment(const std::string& source) {
  if (std::optional<EnvironmentMap> builtin = builtin_environment(source)) return std::move(*builtin);
  return read_hdr_environment(source);
}

EnvironmentDistribution environment_distribution(const EnvironmentMap& map) {
  const int w = map.width, h = map.height;
  EnvironmentDistribution d;
  d.density.resize(static_cast<std::size_t>(w) * h);
  d.marginal.assign(h + 1, 0.0f);
  d.conditional.assign(static_cast<std::size_t>(h) * (w + 1), 0.0f);
  std::vector<double> row_sum(h, 0.0);
  double total = 0.0;
  for (int j = 0; j < h; ++j) {
    const double sin_theta = std::sin(kPi * (j + 0.5) / h);
    double running = 0.0;
    for (int i = 0; i < w; ++i) {
      const double weight = texel_luminance(&map.rgb[(static_cast<std::size_t>(j) * w + i) * 3]) * sin_theta;
      d.density[static_cast<std::size_t>(j) * w + i] = static_cast<float>(weight);
      running += weight;
      d.conditional[static_cast<std::size_t>(j) * (w + 1) + i + 1] = static_cast<float>(running);
    }
    row_sum[j] = running;
    total += running;
  }
  if (!(total > 0.0)) throw std::runtime_error("the environment is black: nothing to light the sphere with");
  // Density over (u, v): weight / (total * du dv).
  const double cells = static_cast<double>(w) * h;
  for (float& value : d.density) value = static_cast<float>(value * cells / total);
  double running = 0.0;
  for (int j = 0; j < h; ++j) {
    for (int i = 1; i <= w; ++i) {
      float& c = d.conditional[static_cast<std::size_t>(j) * (w + 1) + i];
      c = row_sum[j] > 0.0 ? static_cast<float>(c / row_sum[j]) : static_cast<float>(static_cast<double>(i) / w);
    }
    running += row_sum[j];
    d.marginal[j + 1] = static_cast<float>(running / total);
  }
  d.marginal[h] = 1.0f;
  return d;
}

}  // namespace skinlayer
