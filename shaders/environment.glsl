// Environment lighting (app/render/environment_map.h is the CPU twin and states the conventions): radiance along a
// direction of the camera frame from an equirectangular map, and importance sampling by its luminance.

uniform sampler2D u_env;              // RGB radiance, equirectangular, mipmapped (the blurred background)
uniform sampler2D u_env_density;      // R: density over (u, v), piecewise constant per texel
uniform sampler2D u_env_marginal;     // R: (height + 1) x 1, the CDF over rows
uniform sampler2D u_env_conditional;  // R: (width + 1) x height, each row's CDF over columns
uniform float u_env_scale;            // 2^EV
uniform mat3 u_env_from_world;        // R_y(-alpha), the environment turned by alpha about +y (environment_from_world)

vec2 environment_coordinates(vec3 d) {
  float u = atan(d.x, d.z) / (2.0 * kPi);
  return vec2(u < 0.0 ? u + 1.0 : u, acos(clamp(d.y, -1.0, 1.0)) / kPi);
}

vec3 environment_direction(vec2 uv) {
  float theta = kPi * uv.y, phi = 2.0 * kPi * uv.x;
  return vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
}

// The radiance arriving from direction d (seen looking along d), piecewise constant per texel as the sampling
// density is: what lights the sphere.
vec3 environment_radiance(vec3 d) {
  vec2 uv = environment_coordinates(u_env_from_world * d);
  ivec2 size = textureSize(u_env, 0);
  return u_env_scale * texelFetch(u_env, min(ivec2(uv * vec2(size)), size - 1), 0).rgb;
}

// The same filtered for display: bilinear, or blurred from mip level lod > 0.
vec3 environment_background(vec3 d, float lod) {
  vec2 uv = environment_coordinates(u_env_from_world * d);
  return u_env_scale * textureLod(u_env, uv, lod).rgb;
}

// The solid-angle density with which sample_environment picks d.
float environment_pdf(vec3 d) {
  vec2 uv = environment_coordinates(u_env_from_world * d);
  ivec2 size = textureSize(u_env_density, 0);
  ivec2 texel = min(ivec2(uv * vec2(size)), size - 1);
  float sin_theta = sin(kPi * uv.y);
  if (sin_theta <= 0.0) return 0.0;
  return texelFetch(u_env_density, texel, 0).r / (2.0 * kPi * kPi * sin_theta);
}

// The last index k in [0, count - 1) with cdf[k] <= x, for a CDF stored along x of row `row` (count entries).
int find_interval(sampler2D cdf, int row, int count, float x) {
  int low = 0, high = count - 1;
  while (high - low > 1) {
    int middle = (low + high) / 2;
    if (texelFetch(cdf, ivec2(middle, row), 0).r <= x) low = middle; else high = middle;
  }
  return low;
}

// A direction drawn with density environment_pdf from two uniform numbers.
vec3 sample_environment(vec2 xi) {
  ivec2 size = textureSize(u_env_density, 0);
  int j = find_interval(u_env_marginal, 0, size.y + 1, xi.y);
  float c0 = texelFetch(u_env_marginal, ivec2(j, 0), 0).r, c1 = texelFetch(u_env_marginal, ivec2(j + 1, 0), 0).r;
  float v = (float(j) + clamp((xi.y - c0) / max(c1 - c0, 1e-12), 0.0, 1.0)) / float(size.y);
  int i = find_interval(u_env_conditional, j, size.x + 1, xi.x);
  float d0 = texelFetch(u_env_conditional, ivec2(i, j), 0).r, d1 = texelFetch(u_env_conditional, ivec2(i + 1, j), 0).r;
  float u = (float(i) + clamp((xi.x - d0) / max(d1 - d0, 1e-12), 0.0, 1.0)) / float(size.x);
  return transpose(u_env_from_world) * environment_direction(vec2(u, v));  // R_y(alpha): the inverse rotation
}
