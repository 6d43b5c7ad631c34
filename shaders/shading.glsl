// The sphere's shading geometry and its BRDF: what shaders/sphere.frag and shaders/env_accumulate.frag share.
// The sphere is seen by an orthographic camera looking along -z; directions in the camera frame (+z toward the viewer).

uniform float u_eta;    // top interface relative index
uniform float u_sigma;  // top interface RMS slope
uniform int u_microfacet;  // 1: multiple-scattering interfaces (height-correlated masking); 0: single (Stam 2001)

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

// The surface term and the unscattered light [1/sr] at the local angles a (local_angles): the BRDF's parts that leave
// where the light falls.
float surface_brdf(vec3 a) {
  vec3 wi = vec3(sin(a.x), 0.0, cos(a.x));
  vec3 wo = vec3(sin(a.y) * cos(a.z), sin(a.y) * sin(a.z), cos(a.y));
  return microfacet_brdf(wi, wo, u_eta, u_sigma, u_microfacet) + unscattered_brdf(wi, wo);
}

// The material's BRDF per channel [1/sr] for light along l seen along v at normal n (both above the surface):
// surface term + unscattered + subsurface tables, the same sum as core's brdf_total.
vec3 sphere_brdf(vec3 n, vec3 l, vec3 v) {
  vec3 a = local_angles(n, l, v);
  return vec3(surface_brdf(a)) + brdf_subsurface(a.x, a.y, a.z);
}

// The material's subsurface light spread over the sphere by its spatial profile (docs/model.md §21.13): the
// subsurface term takes D(theta), the profile pre-integrated over the sphere's curvature (u_spread_table, per channel,
// theta from 0 to pi across its width), in place of cos(theta), and is read at the incident angle clamped to
// u_spread_max_theta past the terminator. The surface and unscattered terms stay where the light falls.
uniform sampler2D u_spread_table;
uniform float u_spread_max_theta;

vec3 spread_radiance(vec3 n, vec3 l, vec3 v, float irradiance) {
  vec3 a = local_angles(n, l, v);
  float cos_i = dot(n, l);
  vec3 radiance = vec3(0.0);
  if (cos_i > 0.0) radiance = vec3(surface_brdf(a)) * cos_i;
  float width = float(textureSize(u_spread_table, 0).x);
  float u = (a.x / kPi * (width - 1.0) + 0.5) / width;
  vec3 spread = textureLod(u_spread_table, vec2(u, 0.5), 0.0).rgb;
  radiance += brdf_subsurface(min(a.x, u_spread_max_theta), a.y, a.z) * spread;
  return radiance * irradiance;
}

// The sphere's unit normal at the view's point p (in sphere radii), clamped onto the silhouette outside it, so that
// a texture of per-normal values continues past the edge.
vec3 sphere_normal(vec2 p) {
  float r2 = dot(p, p);
  if (r2 >= 1.0) return vec3(p / sqrt(r2), 0.0);
  return vec3(p, sqrt(1.0 - r2));
}
