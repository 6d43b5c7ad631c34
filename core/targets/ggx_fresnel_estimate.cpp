// docs/model.md §22.1.1: Cycles' estimate of a GGX reflection's Fresnel albedo, its table recomputed by quadrature.
#include "core/targets/ggx_fresnel_estimate.h"

#include <algorithm>
#include <cmath>

#include "core/interfaces/fresnel.h"
#include "core/targets/cycles_lookup_table.h"
#include "core/targets/fresnel_terms.h"
#include "core/targets/ggx_energy_compensation.h"
#include "core/targets/ggx_lobe.h"
#include "core/targets/half_vector_quadrature.h"

namespace skinlayer {
namespace {

constexpr int kNodes = 16;  // ggx_gen_schlick_ior_s is 16 x 16 x 16
constexpr double kLeast = 1e-4;
// Quadrature nodes per azimuth for each entry: within 1e-5 of the integral, 3e-4 at the grazing cosine 1e-4; Cycles'
// Monte Carlo (2^20 samples each) is good to about 3e-4.
constexpr int kTablePolar = 24;
constexpr int kGrazingPolar = 64;

// s_bar on the given rules (ggx_visible_fresnel_blend).
double visible_fresnel_blend(const HalfVectorQuadrature& quadrature, double roughness, double mu_o, double eta) {
  const double alpha = roughness * roughness, mu = std::clamp(mu_o, 0.0, 1.0);
  if (cycles_ggx_is_mirror(alpha)) return cycles_fresnel_blend(mu, eta);
  if (mu <= 0.0) return 0.0;
  const Vec3 view(std::sqrt(1.0 - mu * mu), 0.0, mu);
  const double visible = ggx_masking(mu, alpha) / (4.0 * mu);  // G1(mu_o) / (4 mu_o)
  return quadrature.integrate(mu, std::max(alpha, 1e-3), [&](const Vec3& light) {
    const Vec3 h = (light + view).normalized();
    return cycles_fresnel_blend(light.dot(h), eta) * visible * ggx_distribution(h.z(), alpha);
  });
}

// The index of node z: ior_from_F0(z^4).
double node_index(int k) {
  const double z = cycles_node_coordinate(k, kNodes, kLeast, 0.99);
  return cycles_ior_from_f0(z * z * z * z);
}

const CyclesLookupTable& blend_table() {
  static const CyclesLookupTable table(kNodes, kNodes, kNodes, [](int x, int y, int z) {
    // At z = 1e-4 the index is 1 + 2e-8, which Cycles' float arithmetic rounds to 1: s = 0 there.
    if (z == 0) return 0.0;
    static const HalfVectorQuadrature quadrature(kTablePolar), grazing(kGrazingPolar);
    return std::clamp(
        visible_fresnel_blend(y == 0 ? grazing : quadrature, cycles_node_coordinate(x, kNodes, kLeast, 1.0),
                              cycles_node_coordinate(y, kNodes, kLeast, 1.0), node_index(z)),
        0.0, 1.0);
  });
  return table;
}

}  // namespace

double cycles_ior_from_f0(double f0) {
  const double root = std::sqrt(std::clamp(f0, 0.0, 0.99));
  return (1.0 + root) / (1.0 - root);
}

double cycles_fresnel_blend(double cos_ih, double eta) {
  const double f0 = normal_reflectance(eta);
  return std::clamp((fresnel_dielectric(cos_ih, eta) - f0) / (1.0 - f0), 0.0, 1.0);
}

double ggx_visible_fresnel_blend(double roughness, double mu, double eta, int polar) {
  return visible_fresnel_blend(HalfVectorQuadrature(polar), roughness, mu, eta);
}

double cycles_ggx_fresnel_blend(double roughness, double mu, double eta) {
  return blend_table().read(roughness, mu, std::sqrt(std::abs((eta - 1.0) / (eta + 1.0))));
}

Rgb cycles_principled_fresnel_estimate(double roughness, double mu, double eta, const Rgb& f0) {
  const double s = cycles_ggx_fresnel_blend(roughness, mu, eta);
  return f0 * (1.0 - s) + s;
}

double cycles_dielectric_fresnel_estimate(double roughness, double mu, double eta) {
  if (!(eta > 1.0)) return 0.0;  // index 1: no reflection
  const double s = cycles_ggx_fresnel_blend(roughness, mu, eta), f0 = normal_reflectance(eta);
  return f0 * (1.0 - s) + s;
}

}  // namespace skinlayer
