#include "core/unscattered/unscattered_light.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

// e^{-tau/mu}: the slab's transmittance along a direction of cosine mu (> 0); 1 for tau = 0 at any mu.
double attenuation(double tau, double mu) {
  if (tau == 0.0) return 1.0;
  return mu > 0.0 ? std::exp(-tau / mu) : 0.0;
}

// Snell's law in vector form for a ray travelling along p through a facet of normal h facing the ray (p.h < 0),
// eta_rel = n_t / n_i:  t = p / eta_rel + (c / eta_rel - sqrt(1 - (1 - c^2) / eta_rel^2)) h,  c = -p.h.
// Empty under total internal reflection.
std::optional<Vec3> refract(const Vec3& p, const Vec3& h, double eta_rel) {
  const double c = -p.dot(h);
  const double r = 1.0 / eta_rel;
  const double k = 1.0 - r * r * (1.0 - c * c);
  if (k < 0.0) return std::nullopt;
  return Vec3(r * p + (r * c - std::sqrt(k)) * h);
}

// The facet normal of slopes (sx, sy), facing +z (side +1) or -z (side -1).
Vec3 facet_normal(double sx, double sy, double side) { return side * Vec3(-sx, -sy, 1.0).normalized(); }

// A refracted lobe in the projected disk, linearized as a Gaussian to compare the two lobes' widths: centre (the flat
// facet's refraction) and covariance (sigma^2 / 2) J J^T, J the Jacobian of the projected refracted direction by the
// facet slopes at 0 (central differences). `flip` maps the refracted propagation direction to the internal coordinate
// (+1 for light entering through the top, which travels down; -1 for the bottom's lobe, traced backward up from the
// exit direction).
struct Lobe {
  Vec2 centre;
  Mat2 covariance;
};
std::optional<Lobe> refracted_lobe(const Vec3& p, double side, double eta_rel, double sigma, double flip) {
  const auto projected = [&](double sx, double sy) -> std::optional<Vec2> {
    const std::optional<Vec3> t = refract(p, facet_normal(sx, sy, side), eta_rel);
    if (!t) return std::nullopt;
    return Vec2(flip * t->x(), flip * t->y());
  };
  constexpr double kStep = 1e-5;
  const std::optional<Vec2> centre = projected(0.0, 0.0);
  const std::optional<Vec2> xp = projected(kStep, 0.0), xm = projected(-kStep, 0.0);
  const std::optional<Vec2> yp = projected(0.0, kStep), ym = projected(0.0, -kStep);
  if (!centre || !xp || !xm || !yp || !ym) return std::nullopt;
  Mat2 jacobian;
  jacobian.col(0) = (*xp - *xm) / (2.0 * kStep);
  jacobian.col(1) = (*yp - *ym) / (2.0 * kStep);
  // A floor on the covariance keeps the product finite where a lobe degenerates (index ratio -> 1).
  const Mat2 covariance = 0.5 * sigma * sigma * jacobian * jacobian.transpose() + 1e-16 * Mat2::Identity();
  return Lobe{*centre, covariance};
}

// d omega_h / d omega_o for refraction between i (index n_i side) and o (n_o side), eta_o = n_o / n_i, about the
// microfacet normal h (Walter et al. 2007, eq. 17):  eta_o^2 |o.h| / (i.h + eta_o o.h)^2.
double refraction_jacobian(const Vec3& i, const Vec3& o, const Vec3& h, double eta_o) {
  const double denominator = i.dot(h) + eta_o * o.dot(h);
  return eta_o * eta_o * std::abs(o.dot(h)) / (denominator * denominator);
}

// The Beckmann slope density P(p, q) = e^{-(p^2 + q^2) / sigma^2} / (pi sigma^2), and D(h) d omega_h = P dp dq /
// cos(theta_h) with d omega_h = cos^3(theta_h) dp dq: a Gauss-Hermite rule in (p, q) / sigma integrates it exactly.
double slope_density(double p, double q, double sigma) {
  return std::exp(-(p * p + q * q) / (sigma * sigma)) / (kPi * sigma * sigma);
}

// One interface's refraction lobe parameterized by its facet slopes: the internal direction d (travelling down) that
// the facet of slopes (p, q) sends the light to, and weight = f |d.z| (d omega_d / d omega_h) cos^3(theta_h) / P, so
// that  int f(d) g(d) |d.z| d omega_d = int P(p, q) weight g(d(p, q)) dp dq.
struct SlopeSample {
  Vec3 d;
  double weight;
};

// Light from omega_i refracted into the layer by the top's facet (p, q): f = f_t12(omega_i -> d).
std::optional<SlopeSample> sample_entry(const RoughDielectric& top, const Vec3& wi, double p, double q) {
  const Vec3 h = facet_normal(p, q, 1.0);
  if (wi.dot(h) <= 0.0) return std::nullopt;
  const std::optional<Vec3> d = refract(-wi, h, top.eta);
  if (!d || d->z() >= 0.0) return std::nullopt;
  const double f = microfacet_btdf(top, wi, *d);
  if (f == 0.0) return std::nullopt;
  const double cos_h = h.z();
  return SlopeSample{*d, f * -d->z() * cos_h * cos_h * cos_h /
                             (refraction_jacobian(wi, *d, h, top.eta) * slope_density(p, q, top.sigma))};
}

// The exit direction omega_o traced backward up through the bottom's facet (p, q) into the layer: f = f_t23(-d ->
// omega_o); the bottom's frame has +z into the layer and eta = n_below / n_layer.
std::optional<SlopeSample> sample_exit(const RoughDielectric& bottom, const Vec3& wo, double p, double q) {
  const Vec3 h = facet_normal(p, q, 1.0);
  if (wo.dot(h) >= 0.0) return std::nullopt;
  const std::optional<Vec3> up = refract(-wo, -h, 1.0 / bottom.eta);
  if (!up || up->z() <= 0.0) return std::nullopt;
  const Vec3 d = -*up;
  const double f = microfacet_btdf(bottom, -d, wo);
  if (f == 0.0) return std::nullopt;
  const double cos_h = h.z();
  return SlopeSample{d, f * -d.z() * cos_h * cos_h * cos_h /
                            (refraction_jacobian(wo, -d, h, 1.0 / bottom.eta) * slope_density(p, q, bottom.sigma))};
}

// Gauss-Hermite nodes per slope axis: 32 x 32, less the products whose weight is below 1e-15 of the largest (they
// lie beyond ~8 standard deviations of the slope density and add nothing a double can hold).
constexpr int kSlopeNodes = 32;
struct SlopeNode {
  double x, y, weight;  // (p, q) / sigma, and w_a w_b / pi
};
std::vector<SlopeNode> slope_nodes() {
  const QuadratureRule rule = gauss_hermite(kSlopeNodes);
  const double largest = *std::max_element(rule.weights.begin(), rule.weights.end());
  std::vector<SlopeNode> nodes;
  for (int a = 0; a < rule.size(); ++a) {
    for (int b = 0; b < rule.size(); ++b) {
      const double w = rule.weights[a] * rule.weights[b];
      if (w >= 1e-15 * largest * largest) nodes.push_back({rule.nodes[a], rule.nodes[b], w * kInvPi});
    }
  }
  return nodes;
}

}  // namespace

UnscatteredLight::UnscatteredLight(const Material& material,
                                   std::span<const std::shared_ptr<const MultipleScatteringLobe>> built)
    : tau_(material.total_tau()),
      index_below_(material.bottom.kind == BottomKind::Matched
                       ? material.eta * material.internal_index_ratio()
                       : material.eta * material.internal_index_ratio() / material.bottom_eta()) {
  top_ = top_interface(material);
  bottom_ = bottom_interface(material);
  set_path(material);
  // The lobe of a rough interface under MicrofacetModel::Multiple: one already built, or a new one (its modes are
  // not used here; one is the least it holds).
  const auto lobe = [&](const RoughDielectric& interface) -> std::shared_ptr<const MultipleScatteringLobe> {
    if (!has_multiple_scattering(interface)) return nullptr;
    for (const std::shared_ptr<const MultipleScatteringLobe>& given : built) {
      if (given != nullptr && given->interface() == interface) return given;
    }
    return std::make_shared<const MultipleScatteringLobe>(interface, 1);
  };
  if (material.eta != 1.0) top_multiple_ = lobe(top_interface(material));
  if (path_ == UnscatteredPath::BottomOnly) bottom_multiple_ = lobe(bottom_);
}

void UnscatteredLight::set_path(const Material& material) {
  const bool top_open = material.eta == 1.0;
  if (std::isinf(tau_)) return;
  if (material.has_internal_interfaces()) {
    set_stack_path(material);
    return;
  }
  switch (material.bottom.kind) {
    case BottomKind::Lambert:
      return;
    case BottomKind::Matched:
      path_ = top_open ? UnscatteredPath::None : UnscatteredPath::TopOnly;
      return;
    case BottomKind::Air:
      if (material.bottom_eta() == 1.0) {
        path_ = top_open ? UnscatteredPath::None : UnscatteredPath::TopOnly;
      } else {
        path_ = top_open ? UnscatteredPath::BottomOnly : UnscatteredPath::TopThenBottom;
      }
      return;
  }
}

void UnscatteredLight::set_stack_path(const Material& material) {
  // The rough interfaces the unscattered light crosses, top to bottom, each with the optical depth above it.
  struct Crossing {
    RoughDielectric interface;
    double depth_above;
  };
  std::vector<Crossing> crossings;
  if (material.eta != 1.0) crossings.push_back({top_, 0.0});
  double depth = material.tau;
  for (const StackedLayer& layer : material.below) {
    if (layer.interface && layer.interface->eta != 1.0) {
      crossings.push_back({{layer.interface->eta, layer.interface->sigma, material.microfacet}, depth});
    }
    depth += layer.tau;
  }
  if (material.bottom.kind == BottomKind::Lambert) return;
  if (material.bottom.kind == BottomKind::Air && material.bottom_eta() != 1.0) crossings.push_back({bottom_, depth});
  if (crossings.size() == 1) {  // under an open top: the interface between layers (the bottom is not rough)
    path_ = UnscatteredPath::BottomOnly;
    bottom_ = crossings[0].interface;
    tau_ = crossings[0].depth_above;
    tau_after_ = depth - crossings[0].depth_above;
  } else if (crossings.size() == 2) {
    path_ = UnscatteredPath::TopThenBottom;
    top_ = crossings[0].interface;
    bottom_ = crossings[1].interface;
    tau_before_ = crossings[0].depth_above;
    tau_ = crossings[1].depth_above - crossings[0].depth_above;
    tau_after_ = depth - crossings[1].depth_above;
  }
}

double UnscatteredLight::outer_attenuation(const Vec3& wi, const Vec3& wo) const {
  return attenuation(tau_before_, wi.z()) * attenuation(tau_after_, -wo.z());
}

double UnscatteredLight::straight_through_angle(double theta_i) const {
  return std::asin(std::min(1.0, std::sin(theta_i) / index_below_));
}

namespace {

// The incident direction and the exit direction below the layer (graphics convention, radians).
std::pair<Vec3, Vec3> transmission_directions(double theta_i, double theta_o, double phi) {
  return {direction_from_angles(theta_i, 0.0),
          Vec3(std::sin(theta_o) * std::cos(phi), std::sin(theta_o) * std::sin(phi), -std::cos(theta_o))};
}

// A lobe's transmission from above to the exit direction below (wi at azimuth 0, so wo's azimuth is the relative one,
// graphics convention: pi forward), clamped at 0 where its polar interpolation dips below
// (core/interfaces/multiple_scattering.h).
double multiple_transmission(const MultipleScatteringLobe& lobe, const Vec3& wi, const Vec3& wo) {
  return std::max(0.0, lobe.transmission_at(true, wi.z(), -wo.z(), std::atan2(wo.y(), wo.x())));
}

}  // namespace

// The single term of a path through one rough interface (TopOnly, BottomOnly): its single and multiply scattered
// transmission, with the depth crossed after the interface (TopOnly) or before it (BottomOnly); empty otherwise.
std::optional<DepthTerm> UnscatteredLight::one_interface_term(const Vec3& wi, const Vec3& wo) const {
  if (path_ == UnscatteredPath::TopOnly) {
    double f = microfacet_btdf(top_, wi, wo);
    if (top_multiple_) f += multiple_transmission(*top_multiple_, wi, wo);
    return DepthTerm{f, -wo.z()};
  }
  if (path_ == UnscatteredPath::BottomOnly) {
    double f = microfacet_btdf(bottom_, wi, wo);
    if (bottom_multiple_) f += multiple_transmission(*bottom_multiple_, wi, wo);
    return DepthTerm{f, wi.z()};
  }
  return std::nullopt;
}

std::vector<DepthTerm> UnscatteredLight::btdf_terms(double theta_i, double theta_o, double phi) const {
  if (path_ == UnscatteredPath::None) return {};
  const auto [wi, wo] = transmission_directions(theta_i, theta_o, phi);
  std::vector<DepthTerm> terms = path_ == UnscatteredPath::TopThenBottom
                                     ? two_interface_btdf_terms(top_, bottom_, wi, wo)
                                     : std::vector<DepthTerm>{*one_interface_term(wi, wo)};
  const double outer = weight_ * outer_attenuation(wi, wo);
  if (outer != 1.0) {
    for (DepthTerm& term : terms) term.coefficient *= outer;
  }
  return terms;
}

// As sum_depth_terms(btdf_terms()), without a vector for the one-interface paths' single term.
double UnscatteredLight::btdf(double theta_i, double theta_o, double phi) const {
  if (path_ == UnscatteredPath::None) return 0.0;
  if (path_ == UnscatteredPath::TopThenBottom) return sum_depth_terms(btdf_terms(theta_i, theta_o, phi), tau_);
  const auto [wi, wo] = transmission_directions(theta_i, theta_o, phi);
  const DepthTerm term = *one_interface_term(wi, wo);
  return weight_ * term.coefficient * attenuation(tau_, term.mu) * outer_attenuation(wi, wo);
}

UnscatteredLight UnscatteredLight::scaled(double weight) const {
  UnscatteredLight other = *this;
  other.weight_ = weight;
  return other;
}

bool UnscatteredLight::operator==(const UnscatteredLight& other) const {
  return path_ == other.path_ && top_ == other.top_ && bottom_ == other.bottom_ && tau_ == other.tau_ &&
         tau_before_ == other.tau_before_ && tau_after_ == other.tau_after_ && index_below_ == other.index_below_ &&
         weight_ == other.weight_ && (top_multiple_ == nullptr) == (other.top_multiple_ == nullptr) &&
         (bottom_multiple_ == nullptr) == (other.bottom_multiple_ == nullptr);
}

UnscatteredLight UnscatteredLight::at_depth(double tau) const {
  UnscatteredLight other = *this;
  other.tau_ = tau;
  return other;
}

double UnscatteredLight::brdf_single(double theta_i, double theta_o, double phi) const {
  if (path_ != UnscatteredPath::BottomOnly) return 0.0;
  const Vec3 wi = direction_from_angles(theta_i, 0.0);
  const Vec3 wo = direction_from_angles(theta_o, phi);
  return weight_ * attenuation(tau_, wi.z()) * microfacet_brdf(bottom_, wi, wo) * attenuation(tau_, wo.z());
}

UnscatteredLight::MultipleReflections UnscatteredLight::multiple_reflections(double theta_i, double theta_o) const {
  MultipleReflections parts;
  if (top_multiple_) parts.parts[parts.count++] = {top_multiple_.get(), weight_};
  if (bottom_multiple_ && path_ == UnscatteredPath::BottomOnly) {
    parts.parts[parts.count++] = {
        bottom_multiple_.get(), weight_ * attenuation(tau_, std::cos(theta_i)) * attenuation(tau_, std::cos(theta_o))};
  }
  return parts;
}

double UnscatteredLight::brdf(double theta_i, double theta_o, double phi) const {
  if (!reflects()) return 0.0;
  double value = brdf_single(theta_i, theta_o, phi);
  const double mu_i = std::cos(theta_i), mu_o = std::cos(theta_o);
  for (const MultipleReflection& part : multiple_reflections(theta_i, theta_o)) {
    value += part.factor * std::max(0.0, part.lobe->reflection_at(true, mu_i, mu_o, phi));
  }
  return value;
}

std::vector<DepthTerm> two_interface_btdf_terms(const RoughDielectric& top, const RoughDielectric& bottom,
                                                const Vec3& wi, const Vec3& wo) {
  if (wi.z() <= 0.0 || wo.z() >= 0.0) return {};
  // Sample the narrower lobe by its slopes; the other is then the smoother factor.
  const std::optional<Lobe> entry = refracted_lobe(-wi, 1.0, top.eta, top.sigma, 1.0);
  const std::optional<Lobe> exit = refracted_lobe(-wo, -1.0, 1.0 / bottom.eta, bottom.sigma, -1.0);
  const bool by_exit = entry && exit && exit->covariance.determinant() < entry->covariance.determinant();
  static const std::vector<SlopeNode> nodes = slope_nodes();
  std::vector<DepthTerm> terms;
  for (const SlopeNode& node : nodes) {
    if (by_exit) {
      const std::optional<SlopeSample> s = sample_exit(bottom, wo, bottom.sigma * node.x, bottom.sigma * node.y);
      if (!s) continue;
      const double value = node.weight * s->weight * microfacet_btdf(top, wi, s->d);
      if (value != 0.0) terms.push_back({value, -s->d.z()});
    } else {
      const std::optional<SlopeSample> s = sample_entry(top, wi, top.sigma * node.x, top.sigma * node.y);
      if (!s) continue;
      const double value = node.weight * s->weight * microfacet_btdf(bottom, -s->d, wo);
      if (value != 0.0) terms.push_back({value, -s->d.z()});
    }
  }
  return terms;
}

double two_interface_btdf(const RoughDielectric& top, const RoughDielectric& bottom, double tau, const Vec3& wi,
                          const Vec3& wo) {
  return sum_depth_terms(two_interface_btdf_terms(top, bottom, wi, wo), tau);
}

double sum_depth_terms(std::span<const DepthTerm> terms, double tau) {
  double sum = 0.0;
  for (const DepthTerm& term : terms) sum += term.coefficient * attenuation(tau, term.mu);
  return sum;
}

}  // namespace skinlayer
