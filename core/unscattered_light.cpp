#include "core/unscattered_light.h"

#include <Eigen/Dense>
#include <cmath>
#include <optional>

#include "core/material.h"

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

// A refracted lobe in the projected disk, as a Gaussian: centre (the flat facet's refraction) and covariance
// (sigma^2 / 2) J J^T, J the Jacobian of the projected refracted direction by the facet slopes at 0 (central
// differences). `flip` maps the refracted propagation direction to the internal coordinate (+1 for light entering
// through the top, which travels down; -1 for the bottom's lobe, traced backward up from the exit direction).
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

}  // namespace

UnscatteredLight::UnscatteredLight(const Material& material) : tau_(material.tau) {
  const bool top_open = material.eta == 1.0;
  top_ = {material.eta, material.sigma};
  bottom_ = {1.0 / material.bottom_eta(), material.bottom_sigma()};
  if (std::isinf(material.tau)) return;
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

double UnscatteredLight::btdf(double theta_i, double theta_o, double phi) const {
  if (path_ == UnscatteredPath::None) return 0.0;
  const Vec3 wi = direction_from_angles(theta_i, 0.0);
  const Vec3 wo(std::sin(theta_o) * std::cos(phi), std::sin(theta_o) * std::sin(phi), -std::cos(theta_o));
  switch (path_) {
    case UnscatteredPath::TopOnly:
      return microfacet_btdf(top_, wi, wo) * attenuation(tau_, -wo.z());
    case UnscatteredPath::BottomOnly:
      return attenuation(tau_, wi.z()) * microfacet_btdf(bottom_, wi, wo);
    case UnscatteredPath::TopThenBottom:
      return two_interface_btdf(top_, bottom_, tau_, wi, wo);
    case UnscatteredPath::None:
      break;
  }
  return 0.0;
}

double UnscatteredLight::brdf(double theta_i, double theta_o, double phi) const {
  if (path_ != UnscatteredPath::BottomOnly) return 0.0;
  const Vec3 wi = direction_from_angles(theta_i, 0.0);
  const Vec3 wo = direction_from_angles(theta_o, phi);
  return attenuation(tau_, wi.z()) * microfacet_brdf(bottom_, wi, wo) * attenuation(tau_, wo.z());
}

double two_interface_btdf(const RoughDielectric& top, const RoughDielectric& bottom, double tau, const Vec3& wi,
                          const Vec3& wo) {
  if (wi.z() <= 0.0 || wo.z() >= 0.0) return 0.0;
  // Light from the air travelling down into the layer (eta_rel = n_layer / n_air), and the exit direction traced
  // backward: travelling up from below into the layer (eta_rel = n_layer / n_below), then reversed.
  const std::optional<Lobe> entry = refracted_lobe(-wi, 1.0, top.eta, top.sigma, 1.0);
  const std::optional<Lobe> exit = refracted_lobe(-wo, -1.0, 1.0 / bottom.eta, bottom.sigma, -1.0);
  if (!entry || !exit) return 0.0;
  const Mat2 precision_entry = entry->covariance.inverse();
  const Mat2 precision_exit = exit->covariance.inverse();
  const Mat2 covariance = (precision_entry + precision_exit).inverse();
  const Vec2 centre = covariance * (precision_entry * entry->centre + precision_exit * exit->centre);
  const Eigen::SelfAdjointEigenSolver<Mat2> axes(covariance);
  constexpr double kWiden = 1.3;
  const Mat2 frame = axes.eigenvectors() * axes.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal() * kWiden;
  const double area = std::abs(frame.determinant());

  constexpr int kPoints = 25;
  constexpr double kHalfRange = 6.0;
  constexpr double kStep = 2.0 * kHalfRange / (kPoints - 1);
  const double g1_wi = smith_g1_beckmann(wi.z(), top.sigma);
  const double g1_wo = smith_g1_beckmann(wo.z(), bottom.sigma);
  double sum = 0.0;
  for (int a = 0; a < kPoints; ++a) {
    for (int b = 0; b < kPoints; ++b) {
      const Vec2 u(-kHalfRange + a * kStep, -kHalfRange + b * kStep);
      const Vec2 x = centre + frame * u;
      const double r2 = x.squaredNorm();
      if (r2 >= 1.0) continue;
      const Vec3 d(x.x(), x.y(), -std::sqrt(1.0 - r2));
      const double into = microfacet_btdf(top, wi, d, g1_wi, smith_g1_beckmann(d.z(), top.sigma));
      if (into == 0.0) continue;
      const double out = microfacet_btdf(bottom, -d, wo, smith_g1_beckmann(d.z(), bottom.sigma), g1_wo);
      sum += into * attenuation(tau, -d.z()) * out;
    }
  }
  return sum * area * kStep * kStep;
}

}  // namespace skinlayer
