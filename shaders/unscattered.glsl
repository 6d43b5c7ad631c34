// The unscattered part of the layer's BSDF (core/unscattered/unscattered_light.h), which the tables do not hold.
//   * Open top (eta = 1) over a rough bottom: f_R = e^{-tau/mu_i} f_r23(omega_i, omega_o) e^{-tau/mu_o}, in closed
//     form: microfacet_brdf of the bottom seen from inside the layer (eta = n_below / n_layer).
//   * Under multiple-scattering interfaces, the multiply scattered reflection of the interface the light meets first
//     (core/interfaces/multiple_scattering.h), evaluated as MultipleScatteringLobe::reflection_at does: at each pair
//     of its polar grid angles (5 degrees apart) exponential in azimuth between its azimuth samples (linear where a
//     sample is 0), Catmull-Rom in angle between the pairs, clamped at 0. A rough top's as it is; an open top's
//     interface below the slab attenuated both ways, with the single scattering above.
//   * The BTDF of every path, in the plane of incidence only (the lobe plot): app/render/unscattered_plane.h samples
//     it on coordinates centred on the lobe, s = centre + scale sinh(u), u uniform in [u_min, u_max].

uniform int u_unscattered_reflects;  // 1: the open-top closed-form BRDF above applies
uniform float u_tau;                 // optical depth of the slab
uniform float u_bottom_eta;          // n_below / n_layer
uniform float u_bottom_sigma;
uniform int u_bottom_microfacet;  // 1: height-correlated masking (multiple-scattering interfaces); 0: separable
uniform sampler2D u_unscattered_plane;  // R: unscattered BTDF at the samples [1/sr]
uniform vec4 u_unscattered_map;         // (centre, scale, u_min, u_max)

// The multiply scattered reflection lobe (u_multiple_reflects: 0 none, 1 a rough top's, 2 an open top's interface
// under the slab): its samples at (column: azimuth index, row: theta_i index * 19 + theta_o index) [1/sr], its
// azimuths (radians, ascending on [0, pi]) and the channels' weight of it (UnscatteredLight::weight).
const int kMultipleAngles = 19;
const int kMultipleMaxAzimuths = 32;
uniform int u_multiple_reflects;
uniform sampler2D u_multiple_samples;
uniform float u_multiple_azimuths[kMultipleMaxAzimuths];
uniform int u_multiple_azimuth_count;
uniform float u_multiple_weight;

// The Catmull-Rom weights of the polar grid at cosine mu (end values held beyond: indices clamped).
void multiple_polar_weights(float mu, out int index[4], out float weight[4]) {
  float x = acos(clamp(abs(mu), 0.0, 1.0)) / radians(5.0);
  int cell = min(int(x), kMultipleAngles - 2);
  float t = x - float(cell);
  float t2 = t * t;
  float t3 = t2 * t;
  weight[0] = 0.5 * (-t + 2.0 * t2 - t3);
  weight[1] = 0.5 * (2.0 - 5.0 * t2 + 3.0 * t3);
  weight[2] = 0.5 * (t + 4.0 * t2 - 3.0 * t3);
  weight[3] = 0.5 * (-t2 + t3);
  for (int p = 0; p < 4; ++p) index[p] = clamp(cell + p - 1, 0, kMultipleAngles - 1);
}

float multiple_reflection(vec3 wi, vec3 wo) {
  float phi = 0.0;  // graphics convention: pi forward; the lobe is even in phi
  if (length(wi.xy) > 1e-6 && length(wo.xy) > 1e-6) {
    phi = acos(clamp(dot(normalize(wi.xy), normalize(wo.xy)), -1.0, 1.0));
  }
  // The last azimuth sample at or before phi, by bisection.
  int k = 0;
  int hi = u_multiple_azimuth_count - 1;
  if (u_multiple_azimuths[hi] <= phi) k = hi;
  while (hi - k > 1) {
    int mid = (k + hi) / 2;
    if (u_multiple_azimuths[mid] <= phi) k = mid; else hi = mid;
  }
  bool last = k + 1 >= u_multiple_azimuth_count;
  float t = 0.0;
  if (!last) {
    t = clamp((phi - u_multiple_azimuths[k]) / (u_multiple_azimuths[k + 1] - u_multiple_azimuths[k]), 0.0, 1.0);
  }
  int ii[4], io[4];
  float wti[4], wto[4];
  multiple_polar_weights(wi.z, ii, wti);
  multiple_polar_weights(wo.z, io, wto);
  float sum = 0.0;
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      int row = ii[a] * kMultipleAngles + io[b];
      float fa = texelFetch(u_multiple_samples, ivec2(k, row), 0).r;
      float fb = last ? fa : texelFetch(u_multiple_samples, ivec2(k + 1, row), 0).r;
      float f = (fa > 0.0 && fb > 0.0) ? fa * pow(fb / fa, t) : mix(fa, fb, t);
      sum += wti[a] * wto[b] * f;
    }
  }
  return u_multiple_weight * max(sum, 0.0);
}

// e^{-tau/mu}, 1 for tau = 0.
float slab_attenuation(float mu) {
  if (u_tau == 0.0) return 1.0;
  return mu > 0.0 ? exp(-u_tau / mu) : 0.0;
}

float unscattered_brdf(vec3 wi, vec3 wo) {
  float multiple = u_multiple_reflects != 0 ? multiple_reflection(wi, wo) : 0.0;
  if (u_unscattered_reflects == 0) return multiple;
  float single = u_multiple_weight * microfacet_brdf(wi, wo, u_bottom_eta, u_bottom_sigma, u_bottom_microfacet);
  return slab_attenuation(wi.z) * (single + multiple) * slab_attenuation(wo.z);
}

// signed_theta_o > 0: forward (phi = pi); < 0: back toward the light (phi = 0).
float unscattered_btdf_in_plane(float signed_theta_o) {
  float u = asinh((signed_theta_o - u_unscattered_map.x) / u_unscattered_map.y);
  float x = clamp((u - u_unscattered_map.z) / (u_unscattered_map.w - u_unscattered_map.z), 0.0, 1.0);
  float size = float(textureSize(u_unscattered_plane, 0).x);
  return texture(u_unscattered_plane, vec2((x * (size - 1.0) + 0.5) / size, 0.5)).r;
}
