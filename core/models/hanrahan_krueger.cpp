#include "core/models/hanrahan_krueger.h"

#include <cmath>

#include "core/interfaces/fresnel.h"
#include "core/medium/henyey_greenstein.h"

namespace skinlayer {
namespace {

// Refraction into a layer of relative index eta: the cosine of the refracted angle.
double refracted_cosine(double theta, double eta) {
  const double s = std::sin(theta) / eta;
  return std::sqrt(std::max(0.0, 1.0 - s * s));
}

// The phase function between the refracted incident direction of travel (down, azimuth of the light + pi) and an
// outgoing direction of travel with cosine mu_o (signed: > 0 up) at azimuth difference phi (graphics convention).
double phase(const Material& material, double mu_i, double mu_o, double phi) {
  const double s_i = std::sqrt(std::max(0.0, 1.0 - mu_i * mu_i));
  const double s_o = std::sqrt(std::max(0.0, 1.0 - mu_o * mu_o));
  const Vec3 travel_in(-s_i, 0.0, -mu_i);
  const Vec3 travel_out(s_o * std::cos(phi), s_o * std::sin(phi), mu_o);
  return henyey_greenstein(travel_in.dot(travel_out), material.g);
}

}  // namespace

double hanrahan_krueger_brdf_subsurface(const Material& material, double theta_i, double theta_o, double phi) {
  const double eta = material.eta;
  const double mu_i = refracted_cosine(theta_i, eta);
  const double mu_o = refracted_cosine(theta_o, eta);
  if (mu_i <= 0.0 || mu_o <= 0.0) return 0.0;
  const double t12 = 1.0 - fresnel_dielectric(std::cos(theta_i), eta);
  const double t21 = 1.0 - fresnel_dielectric(std::cos(theta_o), eta);  // = 1 - F(mu_o', 1/eta)
  const double depth = -std::expm1(-material.tau * (1.0 / mu_i + 1.0 / mu_o));
  return material.albedo * t12 * t21 * phase(material, mu_i, mu_o, phi) * depth / (eta * eta * (mu_i + mu_o));
}

double hanrahan_krueger_btdf(const Material& material, double theta_i, double theta_o, double phi) {
  if (material.bottom.kind == BottomKind::Lambert || std::isinf(material.tau)) return 0.0;
  const double eta = material.eta;
  const double eta_3 = material.bottom.kind == BottomKind::Air ? material.bottom_eta() : 1.0;
  const double mu_i = refracted_cosine(theta_i, eta);
  const double mu_o = refracted_cosine(theta_o, eta_3);
  if (mu_i <= 0.0 || mu_o <= 0.0) return 0.0;
  const double t12 = 1.0 - fresnel_dielectric(std::cos(theta_i), eta);
  const double t23 = 1.0 - fresnel_dielectric(std::cos(theta_o), eta_3);
  // (e^{-tau/mu_i} - e^{-tau/mu_o}) / (mu_i - mu_o), with its limit tau e^{-tau/mu} / mu^2 at mu_i = mu_o.
  const double tau = material.tau;
  const double difference = mu_i - mu_o;
  const double path = std::abs(difference) < 1e-9
                          ? tau * std::exp(-tau / mu_i) / (mu_i * mu_i)
                          : (std::exp(-tau / mu_i) - std::exp(-tau / mu_o)) / difference;
  return material.albedo * t12 * t23 * phase(material, mu_i, -mu_o, phi) * path / (eta_3 * eta_3);
}

}  // namespace skinlayer
