// A sphere of the material, seen by an orthographic camera looking along -z, under a directional light
//   L = f(omega_i, omega_o) E cos(theta_i),  f = surface term (analytic) + subsurface tables,
// or with the subsurface term spread over the sphere by the material's profile (u_spread, shading.glsl),
// and/or an environment, whose radiance is the progressive estimate of shaders/env_accumulate.frag (a float texture
// over the same view, divided by its sample count). The background is the environment seen through a 53-degree
// perspective (sharp or blurred) or a flat colour.
in vec2 v_ndc;
out vec4 o_color;

uniform vec2 u_extent;        // half-size of the view in sphere radii, per axis (keeps the sphere round)
uniform vec3 u_light;         // unit vector toward the light, camera frame (+z toward the viewer)
uniform float u_irradiance;   // light irradiance on a plane normal to the beam (0: no directional light)
uniform float u_exposure;     // linear multiplier before tone mapping (2^stops)
uniform int u_output_linear;  // 1: write linear radiance (float targets); 0: tone-mapped sRGB
uniform int u_tonemap;        // 0 exponential 1 - e^{-x}, 1 ACES (Narkowicz 2015), 2 none (clamped)
uniform vec3 u_background;    // linear radiance of the flat background
uniform int u_environment;    // 1: add the environment's estimate (u_accumulation) and use its background
uniform sampler2D u_accumulation;  // RGB sum of estimates, A sample count (env_accumulate.frag)
uniform int u_env_background;      // 0 flat colour, 1 the environment sharp, 2 blurred
uniform int u_spread;              // 1: the directional light's subsurface term spread by the profile (shading.glsl)

vec3 encode_srgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

vec3 tone_map(vec3 x) {
  if (u_tonemap == 1) return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
  if (u_tonemap == 2) return clamp(x, 0.0, 1.0);
  return vec3(1.0) - exp(-x);
}

void main() {
  vec2 p = v_ndc * u_extent;
  float r2 = dot(p, p);
  vec3 radiance = u_background;
  if (u_environment == 1 && u_env_background > 0) {
    radiance = environment_background(normalize(vec3(p * (0.5 / u_extent.y), -1.0)), u_env_background == 2 ? 5.0 : 0.0);
  }
  if (r2 <= 1.0) {
    vec3 n = sphere_normal(p);
    vec3 v = vec3(0.0, 0.0, 1.0);
    radiance = vec3(0.0);
    float cos_i = dot(n, u_light);
    if (u_irradiance > 0.0 && u_spread == 1) {
      radiance = spread_radiance(n, u_light, v, u_irradiance);
    } else if (u_irradiance > 0.0 && cos_i > 0.0) {
      radiance = sphere_brdf(n, u_light, v) * u_irradiance * cos_i;
    }
    if (u_environment == 1) {
      vec4 sum = texture(u_accumulation, 0.5 * v_ndc + 0.5);
      if (sum.a > 0.0) radiance += sum.rgb / sum.a;
    }
  }
  if (u_output_linear == 1) {
    o_color = vec4(radiance, 1.0);
  } else {
    o_color = vec4(encode_srgb(tone_map(radiance * u_exposure)), 1.0);
  }
}
