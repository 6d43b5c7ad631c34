// The sharp part of the layer's BSDF: light that crosses the slab without being scattered by the medium, through one
// or two rough interfaces, evaluated exactly at the requested directions (as the surface term is) instead of on the
// discrete ordinates and the tables (48-96 nodes), which cannot hold a lobe narrower than their spacing.
//
// With d the internal propagation direction (d.z < 0, travelling down), omega_i toward the light and omega_o toward
// the viewer below (core/conventions.h; every vector here is in the layer's frame, +z up), and dA = |d.z| d omega_d
// the projected solid angle (the area element of the projected disk (d.x, d.y)):
//
//   rough top, matched bottom (one interface; closed form):
//     f_T(omega_i, omega_o) = f_t12(omega_i -> omega_o) e^{-tau / |omega_o.z|}                               [1/sr]
//   open top (eta = 1), rough bottom (one interface; closed form):
//     f_T(omega_i, omega_o) = e^{-tau / mu_i} f_t23(omega_i -> omega_o)
//     f_R(omega_i, omega_o) = e^{-tau / mu_i} f_r23(omega_i -> omega_o) e^{-tau / mu_o}
//   rough top, rough bottom (two interfaces; a lobe-adapted quadrature over the internal direction):
//     f_T(omega_i, omega_o) = int_disk f_t12(omega_i -> d) e^{-tau / |d.z|} f_t23(-d -> omega_o) dA(d)
//
// f_t12, f_t23, f_r23 are the interfaces' microfacet BSDFs (core/interfaces/microfacet.h), radiance BTDFs, in 1/sr. The
// solver removes exactly these paths from its ordinates (their node-sum images), so the tables carry only light that
// was scattered at least once or reflected between the interfaces, which is smooth; LayerTables adds this part back.
//
// Under MicrofacetModel::Multiple each rough interface also scatters light more than once on its microsurface, into a
// lobe of its own (core/interfaces/multiple_scattering.h, f_ms). Where one interface alone sends the light out, that
// lobe is evaluated exactly here too, beside the single scattering above:
//   every rough top (whatever is below):  f_R += f_ms,r12(omega_i, omega_o)                                      [1/sr]
//   rough top, matched bottom:            f_T += f_ms,t12(omega_i -> omega_o) e^{-tau / |omega_o.z|}
//   open top, rough bottom:               f_R += e^{-tau / mu_i} f_ms,r23(omega_i, omega_o) e^{-tau / mu_o}
//                                         f_T += e^{-tau / mu_i} f_ms,t23(omega_i -> omega_o)
// The lobe is forward and, at grazing light, as sharp in azimuth as a specular lobe: on the tables it would take
// hundreds of Fourier modes. Through two interfaces its convolutions with the other's lobe are smooth, and stay in
// the tables.
// Light reflected by a rough bottom under a rough top without scattering, t12 R23 t21, stays in the tables: its lobe
// is the bottom's reflection lobe (about 2 sigma3 wide inside, against sigma (1 - 1/eta) for a refracted one). Its
// node image is put on four times the ordinates where it matters (core/unscattered/bottom_bounce.h).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/interfaces/microfacet.h"
#include "core/interfaces/multiple_scattering.h"

namespace skinlayer {

struct Material;

enum class UnscatteredPath {
  None,           // nothing crosses unscattered with a BSDF value: semi-infinite, Lambertian base, or no interface
  TopOnly,        // rough top over an index-matched bottom
  BottomOnly,     // open top (eta = 1) over a rough bottom
  TopThenBottom,  // rough top over a rough bottom
};

// One term of the unscattered BTDF's dependence on the optical depth: the BTDF is sum_k coefficient_k e^{-tau/mu_k}
// (mu_k the cosine of an internal direction, > 0; the attenuation is 1 at tau = 0 for any mu).
struct DepthTerm {
  double coefficient;  // [1/sr]
  double mu;
};

// sum_k c_k e^{-tau/mu_k}: the BTDF of those terms at optical depth tau.
double sum_depth_terms(std::span<const DepthTerm> terms, double tau);

// The unscattered part of one material. A value type: default-constructed, it contributes nothing.
class UnscatteredLight {
 public:
  UnscatteredLight() = default;
  // A stack without interfaces between its layers has the unscattered light of one slab of its total depth. With
  // interfaces between layers, the paths above apply to the first one or two rough interfaces the light crosses
  // (the top, those between layers, the bottom), with the depths between them as tau() and those outside them as
  // fixed factors: e^{-tau_before / mu_i} above the first (under an open top the light is not refracted above it) and
  // e^{-tau_after / |omega_o.z|} below the last (over a matched bottom); BottomOnly's reflection is then the first
  // interface's. Three or more rough crossings (a rough top, an interface between layers and a rough bottom) are
  // a convolution of their lobes, wider than each: None, and the light stays in the tables (core/solve/stack_solver.h).
  // `built`: lobes already built for the material's interfaces (a solve's kernels'), shared instead of rebuilt where
  // one is the interface's.
  explicit UnscatteredLight(const Material& material,
                            std::span<const std::shared_ptr<const MultipleScatteringLobe>> built = {});

  UnscatteredPath path() const { return path_; }
  // Whether brdf() can be nonzero: an open top over a rough interface, or a rough top's multiply scattered light.
  bool reflects() const { return path_ == UnscatteredPath::BottomOnly || top_multiple_ != nullptr; }
  // The multiply scattered lobes it evaluates (null where none): the top's (its reflection from above, and its
  // transmission on TopOnly), and on BottomOnly the path's interface's, seen from the layer ("above" in its frame).
  const MultipleScatteringLobe* top_multiple() const { return top_multiple_.get(); }
  const MultipleScatteringLobe* bottom_multiple() const { return bottom_multiple_.get(); }
  // brdf() in its parts: the open top's single scattering off its interface (BottomOnly; 0 otherwise), and the
  // multiply scattered lobes, each with the factor it enters with (the weight, and on BottomOnly the slab's
  // attenuation both ways at the pair): brdf = brdf_single + sum of factor * max(0, lobe.reflection_at(true, ...)).
  double brdf_single(double theta_i, double theta_o, double phi) const;
  struct MultipleReflection {
    const MultipleScatteringLobe* lobe;
    double factor;
  };
  // At most two (the top's, and on BottomOnly its interface's), without an allocation: brdf() is a hot path.
  struct MultipleReflections {
    std::array<MultipleReflection, 2> parts{};
    std::size_t count = 0;
    const MultipleReflection* begin() const { return parts.data(); }
    const MultipleReflection* end() const { return parts.data() + count; }
  };
  MultipleReflections multiple_reflections(double theta_i, double theta_o) const;
  // The same light scaled by `weight`: a mix of channels that share it (core/series/weighted_tables.h).
  UnscatteredLight scaled(double weight) const;
  double weight() const { return weight_; }

  // The unscattered part of the layer BTDF and of the subsurface BRDF, in 1/sr (graphics convention, radians).
  double btdf(double theta_i, double theta_o, double phi) const;
  double brdf(double theta_i, double theta_o, double phi) const;
  // The BTDF's terms in the optical depth: btdf() = sum_depth_terms(btdf_terms(), tau()), for callers that re-weigh
  // the same directions at another depth (the lobe plot, as T changes); the depths outside the path's interfaces
  // are in the coefficients. Empty where the BTDF is 0.
  std::vector<DepthTerm> btdf_terms(double theta_i, double theta_o, double phi) const;
  // The same material at another optical depth (tau in [0, inf)); nothing else changes.
  UnscatteredLight at_depth(double tau) const;

  const RoughDielectric& top() const { return top_; }
  const RoughDielectric& bottom() const { return bottom_; }  // frame +z up into the layer: eta = n_below / n_layer
  double tau() const { return tau_; }
  double tau_before() const { return tau_before_; }  // a stack's depth above the path's first interface
  double tau_after() const { return tau_after_; }    // and below its last

  // The exit angle (radians, from the lower normal, forward) of light at theta_i crossing the layer's flat
  // interfaces: sin(theta_o) = sin(theta_i) / (n_below / n_above), n_below / n_above = eta over a matched bottom and
  // eta / eta3 otherwise; the centre of the unscattered BTDF lobe. Clamped at grazing.
  double straight_through_angle(double theta_i) const;

  // The same light: the same paths, interfaces, depths and weight (the lobes follow from the interfaces).
  bool operator==(const UnscatteredLight& other) const;

 private:
  UnscatteredPath path_ = UnscatteredPath::None;
  void set_path(const Material& material);
  void set_stack_path(const Material& material);
  std::optional<DepthTerm> one_interface_term(const Vec3& wi, const Vec3& wo) const;
  double outer_attenuation(const Vec3& wi, const Vec3& wo) const;  // e^{-tau_before/mu_i} e^{-tau_after/|wo.z|}

  RoughDielectric top_{};
  RoughDielectric bottom_{};
  double tau_ = 0.0;
  double tau_before_ = 0.0;   // above the path's first interface, crossed along the incident direction
  double tau_after_ = 0.0;    // below its last, crossed along the exit direction
  double index_below_ = 1.0;  // n_below / n_above
  double weight_ = 1.0;
  std::shared_ptr<const MultipleScatteringLobe> top_multiple_, bottom_multiple_;  // immutable, shared by copies
};

// f_T of two rough interfaces in sequence (the TopThenBottom formula above) for unit vectors wi (z > 0) and wo
// (z < 0), both in the layer's frame. The quadrature changes variables from the internal direction d to the facet
// slopes (p, q) of the interface whose refraction lobe is narrower (judged by the area of its lobe linearized at the
// flat facet): f |d.z| d omega_d = f (d omega_d / d omega_h) cos^3(theta_h) dp dq (Walter et al. 2007, eq. 17), and
// the Beckmann slope density in f is the Gaussian e^{-(p^2+q^2)/sigma^2} / (pi sigma^2), which a 32 x 32
// Gauss-Hermite rule in (p, q) / sigma integrates exactly. The other interface's lobe, wider, is the smooth factor.
// A Gaussian fitted in the projected disk instead (the first version) was 5-40% off for sigma >= 0.5 at oblique
// angles, where refraction is far from linear in the slope.
double two_interface_btdf(const RoughDielectric& top, const RoughDielectric& bottom, double tau, const Vec3& wi,
                          const Vec3& wo);
// Its quadrature's terms in the optical depth: two_interface_btdf = sum_depth_terms(terms, tau).
std::vector<DepthTerm> two_interface_btdf_terms(const RoughDielectric& top, const RoughDielectric& bottom,
                                                const Vec3& wi, const Vec3& wo);

}  // namespace skinlayer
