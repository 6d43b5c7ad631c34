// Polar lobe plot in the plane of incidence: reflection above the surface line, transmission below. Light arrives
// from the upper left at u_theta_i; the forward (mirror / straight-through) side is the right. The subsurface part
// is filled in one color and the surface part stacked on it in another; circles and 15-degree rays are the grid.
in vec2 v_ndc;
out vec4 o_color;

uniform vec2 u_extent;        // half-size of the view in plot radii, per axis
uniform float u_theta_i;      // incident polar angle
uniform float u_eta;
uniform float u_sigma;
uniform int u_microfacet;  // 1: multiple-scattering interfaces (height-correlated masking); 0: single (Stam 2001)
uniform int u_log_scale;      // 0: radius = f / u_peak; 1: radius = 1 + log10(f / u_peak) / u_decades
uniform float u_peak;         // the BSDF value drawn at radius 1  [1/sr]
uniform float u_decades;      // decades shown by the log scale
uniform int u_output_linear;  // 1: write the plotted radius of the total lobe in R (tests); 0: colors
uniform int u_outline;        // 1: only the total lobe's outline, two pixels wide, over what is already drawn

// The subsurface tables in the plane of incidence at u_theta_i, their modes summed (app/render/lobe_profile.h):
// rows reflection at phi 0 and pi, transmission at phi 0 and pi; columns the tables' theta_o texels.
uniform sampler2D u_lobe_profile;

vec3 in_plane_profile(int row, float theta_o) {
  float v = (float(row) + 0.5) / 4.0;
  return max(texture(u_lobe_profile, vec2(table_coordinate(theta_o), v)).rgb, vec3(0.0));
}

float lobe_radius(float f) {
  if (f <= 0.0) return 0.0;
  if (u_log_scale == 1) return max(0.0, 1.0 + log(f / u_peak) / (log(10.0) * u_decades));
  return f / u_peak;
}

// 1 on a line one pixel wide, fading over the next pixel; pixel is the size of a pixel in plot units.
float line_mask(float distance_to_line, float pixel) {
  return 1.0 - smoothstep(0.5 * pixel, 1.5 * pixel, abs(distance_to_line));
}

void main() {
  vec2 p = v_ndc * u_extent;
  float r = length(p);
  bool reflection = p.y >= 0.0;
  float theta_o = atan(abs(p.x), abs(p.y));
  float phi = p.x >= 0.0 ? kPi : 0.0;
  vec3 wi = vec3(sin(u_theta_i), 0.0, cos(u_theta_i));
  vec3 wo = vec3(sin(theta_o) * cos(phi), 0.0, cos(theta_o));
  float surface = reflection ? microfacet_brdf(wi, wo, u_eta, u_sigma, u_microfacet) : 0.0;
  int forward = p.x >= 0.0 ? 1 : 0;
  vec3 sub = reflection ? in_plane_profile(forward, theta_o) + vec3(unscattered_brdf(wi, wo))
                        : in_plane_profile(2 + forward, theta_o) + vec3(unscattered_btdf_in_plane(p.x >= 0.0 ? theta_o : -theta_o));
  float f_sub = (sub.r + sub.g + sub.b) / 3.0;
  float r_sub = lobe_radius(f_sub);
  float r_total = lobe_radius(f_sub + surface);
  if (u_output_linear == 1) {
    o_color = vec4(r_total, r_sub, r, 1.0);
    return;
  }
  float pixel = length(fwidth(p)) * 0.7071;
  if (u_outline == 1) {  // the A/B comparison's pinned material over the edited one's filled lobes
    if (r_total <= 0.0 || abs(r - r_total) > 1.5 * pixel) discard;
    o_color = vec4(0.95, 0.95, 0.95, 1.0);
    return;
  }
  vec3 color = vec3(0.08);
  if (r < r_sub) color = reflection ? vec3(0.85, 0.45, 0.35) : vec3(0.35, 0.55, 0.85);
  else if (r < r_total) color = vec3(0.95, 0.85, 0.4);
  float grid = 0.0;
  for (int k = 1; k <= 4; ++k) grid = max(grid, line_mask(r - 0.25 * float(k), pixel));
  float angle = atan(p.x, p.y);
  float nearest = round(angle / radians(15.0)) * radians(15.0);
  if (r <= 1.0) grid = max(grid, line_mask(r * sin(angle - nearest), pixel) * 0.6);
  grid = max(grid, line_mask(p.y, pixel) * 2.0);
  vec2 light = vec2(-sin(u_theta_i), cos(u_theta_i));
  float along = dot(p, light);
  if (along > 0.0 && along < 1.1) grid = max(grid, line_mask(p.x * light.y - p.y * light.x, 1.5 * pixel) * 2.0);
  color = mix(color, vec3(0.7), clamp(grid, 0.0, 1.0) * 0.5);
  o_color = vec4(color, 1.0);
}
