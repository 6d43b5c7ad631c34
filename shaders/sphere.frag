// A sphere of the material under a directional light, seen by an orthographic camera looking along -z.
// Radiance L = f(omega_i, omega_o) E cos(theta_i) with f = surface term (analytic) + subsurface tables.
in vec2 v_ndc;
out vec4 o_color;

uniform vec2 u_extent;        // half-size of the view in sphere radii, per axis (keeps the sphere round)
uniform vec3 u_light;         // unit vector toward the light, camera frame (+z toward the viewer)
uniform float u_irradiance;   // light irradiance on a plane normal to the beam
uniform float u_exposure;     // linear multiplier before tone mapping (2^stops)
uniform float u_eta;          // top interface relative index
uniform float u_sigma;        // top interface RMS slope
uniform int u_output_linear;  // 1: write linear radiance (float targets); 0: tone-mapped sRGB
uniform vec3 u_background;    // linear radiance of the background

vec3 encode_srgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

// The shading geometry at normal n: polar angles from n and the azimuth difference about n (pi = mirror side).
vec3 local_angles(vec3 n, vec3 l, vec3 v) {
  float cos_i = clamp(dot(n, l), -1.0, 1.0);
  float cos_o = clamp(dot(n, v), -1.0, 1.0);
  vec3 li = l - cos_i * n;
  vec3 vo = v - cos_o * n;
  float phi = 0.0;
  if (length(li) > 1e-6 && length(vo) > 1e-6) phi = acos(clamp(dot(normalize(li), normalize(vo)), -1.0, 1.0));
  return vec3(acos(cos_i), acos(cos_o), phi);
}

void main() {
  vec2 p = v_ndc * u_extent;
  float r2 = dot(p, p);
  vec3 radiance = u_background;
  if (r2 <= 1.0) {
    vec3 n = vec3(p, sqrt(1.0 - r2));
    vec3 v = vec3(0.0, 0.0, 1.0);
    radiance = vec3(0.0);
    float cos_i = dot(n, u_light);
    if (cos_i > 0.0) {
      vec3 a = local_angles(n, u_light, v);
      vec3 wi = vec3(sin(a.x), 0.0, cos(a.x));
      vec3 wo = vec3(sin(a.y) * cos(a.z), sin(a.y) * sin(a.z), cos(a.y));
      vec3 f = vec3(microfacet_brdf(wi, wo, u_eta, u_sigma) + unscattered_brdf(wi, wo)) + brdf_subsurface(a.x, a.y, a.z);
      radiance = f * u_irradiance * cos_i;
    }
  }
  if (u_output_linear == 1) {
    o_color = vec4(radiance, 1.0);
  } else {
    o_color = vec4(encode_srgb(vec3(1.0) - exp(-radiance * u_exposure)), 1.0);  // exponential tone map
  }
}
