// The unscattered part of the layer's BSDF (core/unscattered/unscattered_light.h), which the tables do not hold.
//   * Open top (eta = 1) over a rough bottom: f_R = e^{-tau/mu_i} f_r23(omega_i, omega_o) e^{-tau/mu_o}, in closed
//     form: microfacet_brdf of the bottom seen from inside the layer (eta = n_below / n_layer).
//   * The BTDF of every path, in the plane of incidence only (the lobe plot): app/render/unscattered_plane.h samples
//     it on coordinates centred on the lobe, s = centre + scale sinh(u), u uniform in [u_min, u_max].

uniform int u_unscattered_reflects;  // 1: the open-top closed-form BRDF above applies
uniform float u_tau;                 // optical depth of the slab
uniform float u_bottom_eta;          // n_below / n_layer
uniform float u_bottom_sigma;
uniform int u_bottom_microfacet;  // 1: height-correlated masking (multiple-scattering interfaces); 0: separable
uniform sampler2D u_unscattered_plane;  // R: unscattered BTDF at the samples [1/sr]
uniform vec4 u_unscattered_map;         // (centre, scale, u_min, u_max)

// e^{-tau/mu}, 1 for tau = 0.
float slab_attenuation(float mu) {
  if (u_tau == 0.0) return 1.0;
  return mu > 0.0 ? exp(-u_tau / mu) : 0.0;
}

float unscattered_brdf(vec3 wi, vec3 wo) {
  if (u_unscattered_reflects == 0) return 0.0;
  return slab_attenuation(wi.z) * microfacet_brdf(wi, wo, u_bottom_eta, u_bottom_sigma, u_bottom_microfacet) * slab_attenuation(wo.z);
}

// signed_theta_o > 0: forward (phi = pi); < 0: back toward the light (phi = 0).
float unscattered_btdf_in_plane(float signed_theta_o) {
  float u = asinh((signed_theta_o - u_unscattered_map.x) / u_unscattered_map.y);
  float x = clamp((u - u_unscattered_map.z) / (u_unscattered_map.w - u_unscattered_map.z), 0.0, 1.0);
  float size = float(textureSize(u_unscattered_plane, 0).x);
  return texture(u_unscattered_plane, vec2((x * (size - 1.0) + 0.5) / size, 0.5)).r;
}
