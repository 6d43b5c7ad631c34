#include "core/reference/microsurface_walk.h"

#include <math.h>  // lgamma_r

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"

namespace skinlayer {
namespace {

constexpr double kSqrtPi = 1.7724538509055160273;
constexpr double kEscaped = std::numeric_limits<double>::infinity();

// The uniform height distribution on [-1, 1]: its cumulative C1 and inverse.
double height_cdf(double h) { return std::clamp(0.5 * (h + 1.0), 0.0, 1.0); }
double height_of_cdf(double c) { return 2.0 * c - 1.0; }

// The height at which a ray from height h along w meets the microsurface, or kEscaped if it leaves it (only an
// upward ray can), in the frame where the microsurface lies below the ray's medium. u is uniform in [0, 1).
double next_height(const Vec3& w, double h, double sigma, double u) {
  if (w.z() > 0.9999999) return kEscaped;                           // straight up: nothing masks it
  if (w.z() < -0.9999999) return height_of_cdf(u * height_cdf(h));  // straight down: Lambda = -1
  if (std::abs(w.z()) < 1e-9) return h;                             // along the mean plane: met at once
  const double lambda = beckmann_lambda(w, sigma);
  const double c1 = height_cdf(h);
  if (w.z() > 0.0 && u > 1.0 - std::pow(c1, lambda)) return kEscaped;  // G1 at height h: C1(h)^Lambda
  return height_of_cdf(std::min(c1 / std::pow(1.0 - u, 1.0 / lambda), 1.0));
}

// The slope x of a visible normal in the standard configuration (sigma 1, the direction in the xz-plane at polar
// cosine c and sine s): density proportional to max(0, c - s x) exp(-x^2) (Heitz & d'Eon 2014), by inverting its
// cumulative
//   F(x) = c sqrt(pi)/2 erfc(-x) + s/2 exp(-x^2),   x <= c/s,
// with Newton steps kept inside a bisection bracket. The search starts at min(0, x_max/2), x_max = c/s, near the
// density's bulk (or mid-bracket where that is outside it), and stops once a Newton step moves x by less than
// 1e-12 (or hits the root): about 6 evaluations of F on average. (Stopping on the bracket's width alone bisected
// on for 18 after convergence.)
double visible_slope_x(double c, double s, double u) {
  const auto cumulative = [c, s](double x) { return 0.5 * c * kSqrtPi * std::erfc(-x) + 0.5 * s * std::exp(-x * x); };
  double hi = s > 1e-12 ? c / s : 9.0;
  double lo = std::min(hi, 0.0) - 9.0;
  const double target = u * cumulative(hi);
  double x = std::min(0.0, 0.5 * hi);
  if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);  // a direction below the horizon (c < 0): x_max < 0
  for (int iteration = 0; iteration < 100 && hi - lo > 1e-13; ++iteration) {
    const double residual = cumulative(x) - target;
    if (residual == 0.0) return x;
    if (residual > 0.0)
      hi = x;
    else
      lo = x;
    const double slope = (c - s * x) * std::exp(-x * x);  // F'(x)
    const double newton = slope > 0.0 ? x - residual / slope : x;
    if (slope > 0.0 && std::abs(newton - x) < 1e-12) return newton;
    x = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
  }
  return x;
}

}  // namespace

double beckmann_lambda(const Vec3& w, double sigma) {
  const double mu = std::clamp(w.z(), -1.0, 1.0);
  const double sine = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  if (sine == 0.0) return mu > 0.0 ? 0.0 : -1.0;
  if (mu == 0.0) return std::numeric_limits<double>::infinity();
  const double a = std::abs(mu) / (sigma * sine);
  const double upward = -0.5 * std::erfc(a) + std::exp(-a * a) / (2.0 * a * kSqrtPi);  // Lambda of (|mu|)
  return mu > 0.0 ? upward : -1.0 - upward;
}

double height_correlated_bsdf(const RoughDielectric& interface, const Vec3& wi, const Vec3& wo) {
  if (interface.eta == 1.0 || wi.z() == 0.0 || wo.z() == 0.0) return 0.0;
  const double side = wi.z() > 0.0 ? 1.0 : -1.0;
  // Both directions as seen from wi's side (z > 0 there), where the masking functions are defined.
  const Vec3 i = side * wi, o = side * wo;
  const double lambda_i = beckmann_lambda(i, interface.sigma);
  const double eta_rel = side > 0.0 ? interface.eta : 1.0 / interface.eta;  // n beyond the boundary / n on wi's side
  if (o.z() > 0.0) {                                                        // reflection
    Vec3 h = i + o;
    if (h.norm() == 0.0) return 0.0;
    h.normalize();
    if (i.dot(h) <= 0.0 || o.dot(h) <= 0.0) return 0.0;
    const double g2 = 1.0 / (1.0 + lambda_i + beckmann_lambda(o, interface.sigma));
    return fresnel_dielectric(i.dot(h), eta_rel) * beckmann_ndf(h.z(), interface.sigma) * g2 / (4.0 * i.z() * o.z());
  }
  // Transmission: eta_t = n_wo_side / n_wi_side; h = -(i + eta_t o), flipped up.
  const double eta_t = eta_rel;
  Vec3 h = -(i + eta_t * o);
  h.normalize();
  if (h.z() < 0.0) h = -h;
  const double i_h = i.dot(h), o_h = o.dot(h);
  if (i_h <= 0.0 || o_h >= 0.0) return 0.0;  // i sees the front of h, o (below) its back
  const double fresnel = fresnel_dielectric(i_h, eta_t);
  if (fresnel >= 1.0) return 0.0;
  const double lambda_o = beckmann_lambda(-o, interface.sigma);  // o seen from its own side
  int sign = 0;  // lgamma_r keeps the sign out of the global signgam, so walks on several threads do not race
  const double g2 = std::exp(::lgamma_r(1.0 + lambda_i, &sign) + ::lgamma_r(1.0 + lambda_o, &sign) -
                             ::lgamma_r(2.0 + lambda_i + lambda_o, &sign));  // B(1 + Lambda_i, 1 + Lambda_o)
  const double denominator = i_h + eta_t * o_h;
  return i_h * std::abs(o_h) * eta_t * eta_t * (1.0 - fresnel) * beckmann_ndf(h.z(), interface.sigma) * g2 /
         (i.z() * std::abs(o.z()) * denominator * denominator);
}

MicrosurfaceScatterDensity::MicrosurfaceScatterDensity(const RoughDielectric& interface, bool from_above, const Vec3& w)
    : sigma_(interface.sigma),
      eta_(from_above ? interface.eta : 1.0 / interface.eta),
      area_(interface.eta == 1.0 ? 0.0 : w.z() * (1.0 + beckmann_lambda(w, interface.sigma))),
      w_(w) {}

double MicrosurfaceScatterDensity::operator()(const Vec3& o) const {
  if (!(area_ > 0.0)) return 0.0;  // no interface, or a ray straight down that no facet faces
  if (o.z() > 0.0) {
    const Vec3 sum = w_ + o;
    const double norm = sum.norm();
    if (norm == 0.0) return 0.0;
    const Vec3 h = sum / norm;
    const double w_h = w_.dot(h);
    if (h.z() <= 0.0 || w_h <= 0.0 || o.dot(h) <= 0.0) return 0.0;
    return fresnel_dielectric(w_h, eta_) * beckmann_ndf(h.z(), sigma_) / (4.0 * area_);
  }
  Vec3 h = -(w_ + eta_ * o);
  const double norm = h.norm();
  if (norm == 0.0) return 0.0;
  h /= norm;
  if (h.z() < 0.0) h = -h;
  const double w_h = w_.dot(h), o_h = o.dot(h);
  if (w_h <= 0.0 || o_h >= 0.0) return 0.0;
  const double fresnel = fresnel_dielectric(w_h, eta_);
  if (fresnel >= 1.0) return 0.0;
  const double denominator = w_h + eta_ * o_h;
  return (1.0 - fresnel) * beckmann_ndf(h.z(), sigma_) * w_h * -o_h * eta_ * eta_ / (area_ * denominator * denominator);
}

MicrosurfaceWalk::MicrosurfaceWalk(RoughDielectric interface) : interface_(interface) {}

Vec3 MicrosurfaceWalk::visible_normal(const Vec3& w, std::mt19937_64& random) const {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, std::sqrt(0.5));  // exp(-y^2): Beckmann's slopes at sigma 1
  const double sigma = interface_.sigma;
  // Stretch to sigma 1, where the slopes across the direction's plane are independent of those along it.
  Vec3 stretched(sigma * w.x(), sigma * w.y(), w.z());
  stretched.normalize();
  const double s = std::hypot(stretched.x(), stretched.y());
  const double c = stretched.z();
  const double along = visible_slope_x(c, s, uniform(random));
  const double across = normal(random);
  const double cos_phi = s > 0.0 ? stretched.x() / s : 1.0, sin_phi = s > 0.0 ? stretched.y() / s : 0.0;
  const double x = sigma * (cos_phi * along - sin_phi * across);
  const double y = sigma * (sin_phi * along + cos_phi * across);
  return Vec3(-x, -y, 1.0).normalized();
}

MicrosurfaceExit MicrosurfaceWalk::walk(const Vec3& wi, std::mt19937_64& random) const {
  return walk(wi, random, MeetingVisitor{});
}

MicrosurfaceExit MicrosurfaceWalk::walk(const Vec3& wi, std::mt19937_64& random, const MeetingVisitor& visit) const {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  if (interface_.eta == 1.0) return {-wi, 1};
  bool above = wi.z() > 0.0;           // the ray is in the medium above the microsurface
  Vec3 ray = -wi;                      // the direction it travels
  double height = above ? 1.0 : -1.0;  // beyond every point of the microsurface on the light's side
  for (int order = 0;; ++order) {
    // In the frame of the ray's medium the microsurface lies below: seen from below, heights and directions negate.
    const double side = above ? 1.0 : -1.0;
    const double next = next_height(side * ray, side * height, interface_.sigma, uniform(random));
    if (next == kEscaped || order >= kMaxOrder) return {ray, std::max(order, 1)};
    height = side * next;
    // Scatter at the microfacet: w is the ray reversed, in the frame of its medium.
    const Vec3 w = -side * ray;
    if (visit) visit(MicrosurfaceMeeting{order + 1, above, w, height_cdf(next)});
    const Vec3 m = visible_normal(w, random);
    const double eta = above ? interface_.eta : 1.0 / interface_.eta;  // n of the other medium / n of this one
    const double cos_i = std::max(w.dot(m), 1e-12);
    const FresnelRefraction fresnel = fresnel_refraction(cos_i, eta);
    Vec3 out;
    if (uniform(random) < fresnel.reflectance) {
      out = -w + 2.0 * cos_i * m;
    } else {
      out = (-w / eta + (cos_i / eta - fresnel.cos_transmitted) * m).normalized();
      above = !above;
    }
    ray = side * out;  // back to the world frame
  }
}

}  // namespace skinlayer
