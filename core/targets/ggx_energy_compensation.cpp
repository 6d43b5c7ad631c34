// docs/model.md §22.1.1: Cycles' GGX energy compensation, its tables recomputed by quadrature.
#include "core/targets/ggx_energy_compensation.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "core/series/quadrature.h"
#include "core/targets/cycles_lookup_table.h"
#include "core/targets/ggx_lobe.h"
#include "core/targets/half_vector_quadrature.h"

namespace skinlayer {
namespace {

constexpr int kNodes = 32;       // Cycles' ggx_E is 32 x 32, ggx_Eavg 32
constexpr double kLeast = 1e-4;  // the generator's clamp of roughness and cosine
// Quadrature nodes per azimuth for each entry: within 1e-4 of the integral (1e-6 away from grazing views), as close
// as Cycles' own Monte Carlo estimates (2^23 samples each: about 1e-4). At the grazing cosine 1e-4 half vectors
// converge slowly and take more (within 3e-4 there).
constexpr int kTablePolar = 48;
constexpr int kGrazingPolar = 128;
constexpr int kAverageCosines = 24;  // Gauss-Legendre cosines for E_avg

double white(double) { return 1.0; }

const HalfVectorQuadrature& table_quadrature() {
  static const HalfVectorQuadrature quadrature(kTablePolar);
  return quadrature;
}

double node_roughness(int i) { return cycles_node_coordinate(i, kNodes, kLeast, 1.0); }

double albedo_node(int roughness_node, int cosine_node) {
  const double r = node_roughness(roughness_node);
  const double mu = cycles_node_coordinate(cosine_node, kNodes, kLeast, 1.0);
  const double E = cosine_node == 0 ? ggx_reflection_albedo(r * r, mu, white, kGrazingPolar)
                                    : ggx_reflection_albedo(table_quadrature(), r * r, mu, white);
  return std::clamp(E, 0.0, 1.0);
}

// E_avg(r) = 2 int_0^1 E(mu) mu dmu; Cycles averages 2 mu E(mu) over uniform random cosines (not clamped).
double average_albedo_node(int roughness_node) {
  const double r = node_roughness(roughness_node);
  const QuadratureRule mu = gauss_legendre(kAverageCosines, 0.0, 1.0);
  double sum = 0.0;
  for (int k = 0; k < mu.size(); ++k) {
    const double m = mu.nodes[static_cast<std::size_t>(k)];
    sum +=
        mu.weights[static_cast<std::size_t>(k)] * 2.0 * m * ggx_reflection_albedo(table_quadrature(), r * r, m, white);
  }
  return std::clamp(sum, 0.0, 1.0);
}

// Computed on first use and never changed: no mutable state.
const CyclesLookupTable& albedo_table() {
  static const CyclesLookupTable table(kNodes, kNodes, 1, [](int x, int y, int) { return albedo_node(x, y); });
  return table;
}

const CyclesLookupTable& average_albedo_table() {
  static const CyclesLookupTable table(kNodes, 1, 1, [](int x, int, int) { return average_albedo_node(x); });
  return table;
}

}  // namespace

double ggx_reflection_albedo(double alpha, double mu_o, const std::function<double(double)>& fresnel, int polar) {
  return ggx_reflection_albedo(HalfVectorQuadrature(polar), alpha, mu_o, fresnel);
}

double ggx_reflection_albedo(const HalfVectorQuadrature& quadrature, double alpha, double mu_o,
                             const std::function<double(double)>& fresnel) {
  const double mu = std::clamp(mu_o, 0.0, 1.0);
  if (cycles_ggx_is_mirror(alpha)) return fresnel(mu);
  if (mu <= 0.0) return 0.0;
  const Vec3 view(std::sqrt(1.0 - mu * mu), 0.0, mu);
  return quadrature.integrate(mu, std::max(alpha, 1e-3), [&](const Vec3& light) {
    const Vec3 h = (light + view).normalized();
    return fresnel(light.dot(h)) * ggx_distribution(h.z(), alpha) *
           ggx_height_correlated_masking(light.z(), mu, alpha) / (4.0 * mu);
  });
}

double cycles_ggx_albedo(double roughness, double mu) { return albedo_table().read(roughness, mu); }

double cycles_ggx_average_albedo(double roughness) { return average_albedo_table().read(roughness); }

double cycles_ggx_albedo_node(int roughness_node, int cosine_node) {
  return albedo_table().node(roughness_node, cosine_node);
}

double cycles_ggx_average_albedo_node(int roughness_node) { return average_albedo_table().node(roughness_node); }

double cycles_dielectric_average_fresnel(double eta) {
  if (eta < 1.0) return 0.997118 + eta * (0.1014 - eta * (0.965241 + eta * 0.130607));
  return (eta - 1.0) / (4.08567 + 1.00071 * eta);
}

Rgb cycles_ggx_energy_factor(double roughness, double mu, const Rgb& average_fresnel) {
  const double E = cycles_ggx_albedo(roughness, mu), E_avg = cycles_ggx_average_albedo(roughness);
  const double missing = (1.0 - E) / E;
  const Rgb multiple = average_fresnel * E_avg / (1.0 - average_fresnel * (1.0 - E_avg));
  return 1.0 + multiple * missing;
}

}  // namespace skinlayer
