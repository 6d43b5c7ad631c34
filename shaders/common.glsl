// GLSL twins of core's fresnel_dielectric, beckmann_ndf, smith_g1_beckmann and microfacet_brdf
// (core/interfaces/fresnel.h, core/interfaces/microfacet.h): the same equations, in float. Directions are unit vectors
// in the local frame (z = macro normal), pointing away from the surface. BRDF values in 1/sr.

const float kPi = 3.14159265358979;

// erf by Abramowitz & Stegun 7.1.26 (absolute error < 1.5e-7).
float erf_approx(float x) {
  float s = sign(x);
  float a = abs(x);
  float t = 1.0 / (1.0 + 0.3275911 * a);
  float y = 1.0 - (((((1.061405429 * t - 1.453152027) * t) + 1.421413741) * t - 0.284496736) * t + 0.254829592) * t *
                      exp(-a * a);
  return s * y;
}

// Unpolarized Fresnel reflectance, Cook & Torrance form; eta = n_t / n_i; 1 under total internal reflection.
float fresnel_dielectric(float cos_incident, float eta) {
  float c = abs(cos_incident);
  float g2 = eta * eta + c * c - 1.0;
  if (g2 <= 0.0) return 1.0;
  float g = sqrt(g2);
  float a = (g - c) / (g + c);
  float b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * a * a * (1.0 + b * b);
}

// Beckmann NDF, sigma = RMS slope: exp(-tan^2/sigma^2) / (pi sigma^2 cos^4).  [1/sr]
float beckmann_ndf(float cos_alpha, float sigma) {
  if (cos_alpha <= 0.0) return 0.0;
  float c2 = cos_alpha * cos_alpha;
  float t2 = (1.0 - c2) / c2;
  float s2 = sigma * sigma;
  return exp(-t2 / s2) / (kPi * s2 * c2 * c2);
}

// Exact Smith G1 for Beckmann: 1 / (1 + Lambda(a)), a = 1/(sigma tan theta).
float smith_g1_beckmann(float cos_theta, float sigma) {
  float c = min(abs(cos_theta), 1.0);
  float s = sqrt(max(0.0, 1.0 - c * c));
  if (s == 0.0) return 1.0;
  if (c == 0.0) return 0.0;
  float a = c / (sigma * s);
  if (a > 8.0) return 1.0;
  float lambda = 0.5 * (erf_approx(a) - 1.0) + exp(-a * a) / (2.0 * a * sqrt(kPi));
  return 1.0 / (1.0 + lambda);
}

// Smith masking-shadowing in reflection (core's smith_g2_reflection): separable G1 G1 for the single-scattering
// model (height_correlated 0, Stam 2001), height-correlated 1 / (1 + Lambda_i + Lambda_o) for the multiple one.
float smith_g2_reflection(float g1_i, float g1_o, int height_correlated) {
  if (g1_i <= 0.0 || g1_o <= 0.0) return 0.0;
  if (height_correlated == 0) return g1_i * g1_o;
  return 1.0 / (1.0 / g1_i + 1.0 / g1_o - 1.0);
}

// The rough-dielectric BRDF seen from above, eta = n_below / n_above (the surface term).
float microfacet_brdf(vec3 wi, vec3 wo, float eta, float sigma, int height_correlated) {
  if (wi.z <= 0.0 || wo.z <= 0.0 || eta == 1.0) return 0.0;
  vec3 h = normalize(wi + wo);
  if (dot(wi, h) <= 0.0 || dot(wo, h) <= 0.0) return 0.0;
  float g = smith_g2_reflection(smith_g1_beckmann(wi.z, sigma), smith_g1_beckmann(wo.z, sigma), height_correlated);
  return fresnel_dielectric(dot(wi, h), eta) * beckmann_ndf(h.z, sigma) * g / (4.0 * wi.z * wo.z);
}
