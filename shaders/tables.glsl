// Evaluation of the subsurface tables (layout: table_layout.h, prefixed to this file).

uniform sampler2DArray u_reflection;
uniform sampler2DArray u_transmission;
uniform int u_modes;

// Texture coordinate of a polar angle on the tables' grid map.
float table_coordinate(float theta) {
  float x = asin(clamp(theta / (0.5 * kPi), 0.0, 1.0)) / (0.5 * kPi);
  float size = float(textureSize(u_reflection, 0).x);
  return (x * (size - 1.0) + 0.5) / size;
}

// textureLod: the tables have one level, and the environment's estimate sums them in non-uniform control flow,
// where the implicit derivatives of texture() are undefined (GLSL 4.60, 8.9).
vec3 sum_fourier_modes(sampler2DArray table, float theta_i, float theta_o, float phi) {
  vec2 uv = vec2(table_coordinate(theta_o), table_coordinate(theta_i));
  vec3 value = vec3(0.0);
  for (int m = 0; m < u_modes; ++m) value += textureLod(table, vec3(uv, float(m)), 0.0).rgb * cos(float(m) * phi);
  return max(value, vec3(0.0));
}

// Subsurface BRDF and layer BTDF per color channel [1/sr]; theta from the normal of the direction's side,
// phi = phi_o - phi_i (pi = forward). Clamped at 0 as core/series/layer_tables.h does (spline undershoot beside sharp
// lobes).
vec3 brdf_subsurface(float theta_i, float theta_o, float phi) { return sum_fourier_modes(u_reflection, theta_i, theta_o, phi); }
vec3 btdf_layer(float theta_i, float theta_o, float phi) { return sum_fourier_modes(u_transmission, theta_i, theta_o, phi); }
