// Environment lighting: radiance arriving from every direction, as an equirectangular image of linear RGB radiance
// (the units of the directional light's irradiance per steradian), and the luminance distribution that importance
// samples it (shaders/environment.glsl is its GLSL twin).
//
// Directions are in the camera frame of shaders/sphere.frag (+x right, +y up, +z toward the viewer). Texel (i, j) of
// a W x H map covers u in [i, i + 1) / W, v in [j, j + 1) / H (row 0 at the top), with
//   theta = pi v (from +y),  phi = 2 pi u,  d = (sin theta sin phi, cos theta, sin theta cos phi),
// so the map's centre (u = 0.5) lies behind the sphere (-z) and its left and right edges in front of it (+z).
// A rotation by alpha turns the environment about +y: the radiance along d is the map's along R_y(-alpha) d.
// The solid angle of a texel is (2 pi / W)(pi / H) sin theta.
#pragma once

#include <array>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skinlayer {

struct EnvironmentMap {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;  // width * height * 3, row 0 (theta = 0, straight up) first
};

// The built-in environments (no asset files): "furnace" (uniform radiance 1), "studio" (an overhead softbox and two
// strip lights over a dim gradient), "sky" (a sun and a sky gradient over a dim ground). nullopt for another name.
std::optional<EnvironmentMap> builtin_environment(std::string_view name);
inline constexpr std::array<std::string_view, 3> kBuiltinEnvironments = {"furnace", "studio", "sky"};

// An equirectangular Radiance .hdr file (stb_image), from its bytes (`source` names it in errors) or its path.
// Throws std::runtime_error naming the file: unreadable, not an HDR image, damaged or truncated, not twice as wide as
// high (within one pixel), or wider than kMaxEnvironmentWidth (the sizes are checked in the header, before any pixel
// is decoded). Negative and non-finite texels read as 0.
inline constexpr int kMaxEnvironmentWidth = 8192;  // 8K x 4K: 384 MiB of float RGB
EnvironmentMap decode_hdr_environment(std::string_view bytes, std::string_view source);
EnvironmentMap read_hdr_environment(const std::string& path);

// What `render --env` and the previewer accept: a built-in's name, else a .hdr path (read_hdr_environment's errors).
EnvironmentMap load_environment(const std::string& source);

// The unit direction at the centre of texel coordinates (u, v) in [0, 1]^2, and back.
glm::dvec3 environment_direction(double u, double v);
glm::dvec2 environment_coordinates(const glm::dvec3& direction);

// The rotation that takes a world direction d to the map's frame, R_y(-alpha) d, for an environment turned by alpha
// radians about +y (shaders/environment.glsl applies it as u_env_from_world).
glm::dmat3 environment_from_world(double alpha);

// Importance sampling of an environment by luminance: the density over (u, v) proportional to
// Y(texel) sin(theta), piecewise constant per texel, normalized so that it integrates to 1 over [0, 1]^2; its
// marginal CDF over rows and each row's conditional CDF over columns. The solid-angle density of a direction is
// density(u, v) / (2 pi^2 sin theta).
struct EnvironmentDistribution {
  std::vector<float> density;      // width * height
  std::vector<float> marginal;     // height + 1, from 0 to 1
  std::vector<float> conditional;  // height rows of width + 1, each from 0 to 1
};
EnvironmentDistribution environment_distribution(const EnvironmentMap& map);

}  // namespace skinlayer
