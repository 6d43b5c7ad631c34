// The rough dielectric BSDF (microfacet.h) of one pair of polar angles as a function of the azimuth difference only:
// what the interface operators' Fourier projection samples (core/interfaces/interface_operators.cpp). Everything that
// depends on the polar angles alone is computed once per pair; each azimuth then costs one square root, one exp and
// the Fresnel factor, in a loop over contiguous cosines.
//
// With wi = (-s_i, 0, z_i) and wo = (s_o cos phi, s_o sin phi, z_o) (graphics convention, unit vectors), and the
// versine v = 1 - cos phi (computed without cancellation near phi = 0), the half vector of microfacet.h is
// h ~ wi + b wo with b = 1 for reflection and b = eta_t for transmission, whose parts are
//   |h_xy|^2 = (s_i - b s_o)^2 + 2 b s_i s_o v,   h_z = z_i + b z_o,   tan^2 theta_h = |h_xy|^2 / h_z^2,
// free of the cancellation that 1 + wi.wo suffers for nearly opposite grazing directions. Then
//   reflection (z_i z_o > 0):  wi.h = |wi + wo| / 2,   f_r = F(wi.h, eta_rel) D G2 / (4 |z_i| |z_o|);
//   transmission (z_i z_o < 0), L = |wi + eta_t wo|, h = s (wi + eta_t wo) / L with the sign s that makes h_z >= 0,
//   w = wi.wo = z_i z_o - s_i s_o + s_i s_o v:
//                              wi.h = s (1 + eta_t w) / L,  wo.h = s (w + eta_t) / L,  wi.h + eta_t wo.h = s L,
//                              f_t = |wi.h| |wo.h| eta_t^2 (1 - F(wi.h, eta_t)) D G2 / (|z_i| |z_o| L^2),
//                              zero unless (wi.h) z_i > 0 and (wo.h) z_o > 0 (neither sees the back of h);
// with pi sigma^2 D = exp(-tan^2 / sigma^2) (1 + tan^2)^2 and G2 the interface's masking-shadowing of the pair
// (core/interfaces/smith_masking.h), which depends on the polar angles alone. Reflection always passes the masking test. In 1/sr, not
// cosine-weighted; 0 at eta = 1.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/interfaces/microfacet.h"
#include "core/interfaces/smith_masking.h"

namespace skinlayer {

class InterfaceAzimuthSweep {
 public:
  // wi with wi.y = 0 (the projection's frame); cos_to the signed z of wo; g1_wi, g1_wo the Smith factors of the
  // two polar angles.
  InterfaceAzimuthSweep(const RoughDielectric& interface, const Vec3& wi, double cos_to, double g1_wi, double g1_wo)
      : inverse_sigma2_(1.0 / (interface.sigma * interface.sigma)), z_i_(wi.z()), z_o_(cos_to) {
    s_i_ = -wi.x();
    s_o_ = std::sqrt(std::max(0.0, 1.0 - cos_to * cos_to));
    reflection_ = z_i_ * z_o_ > 0.0;
    eta_ = z_i_ > 0.0 ? interface.eta : 1.0 / interface.eta;  // eta_rel, or eta_t: n of the far side / n of wi's
    b_ = reflection_ ? 1.0 : eta_;
    const double cosines = std::abs(z_i_) * std::abs(z_o_);
    absent_ = interface.eta == 1.0 || cosines == 0.0;
    if (absent_) return;
    const double g = reflection_ ? smith_g2_reflection(g1_wi, g1_wo, interface.microfacet)
                                 : smith_g2_transmission(g1_wi, g1_wo, interface.microfacet);
    const double pi_sigma2 = kPi * interface.sigma * interface.sigma;
    scale_ = reflection_ ? g / (4.0 * cosines * pi_sigma2) : eta_ * eta_ * g / (cosines * pi_sigma2);
    h_z_ = z_i_ + b_ * z_o_;
    tilt_ = (s_i_ - b_ * s_o_) * (s_i_ - b_ * s_o_);
    cross_ = 2.0 * b_ * s_i_ * s_o_;
  }

  // The BSDF at the azimuth with cosine cos_phi and sine sin_phi >= 0.
  double at_azimuth(double cos_phi, double sin_phi) const {
    if (absent_ || h_z_ == 0.0) return 0.0;  // h on the horizon: D = 0
    const double versine = cos_phi > 0.0 ? sin_phi * sin_phi / (1.0 + cos_phi) : 1.0 - cos_phi;
    const double h_xy2 = tilt_ + cross_ * versine;
    const double h_z2 = h_z_ * h_z_;
    const double length2 = h_xy2 + h_z2;
    const double tan2 = h_xy2 / h_z2;
    const double beckmann = std::exp(-tan2 * inverse_sigma2_) * (1.0 + tan2) * (1.0 + tan2);  // pi sigma^2 D
    if (reflection_) return fresnel_dielectric(0.5 * std::sqrt(length2), eta_) * beckmann * scale_;
    const double w = z_i_ * z_o_ - s_i_ * s_o_ + s_i_ * s_o_ * versine;
    const double sign = h_z_ > 0.0 ? 1.0 : -1.0;
    const double i_h = sign * (1.0 + eta_ * w);  // times L
    const double o_h = sign * (w + eta_);        // times L
    if (i_h * z_i_ <= 0.0 || o_h * z_o_ <= 0.0) return 0.0;
    const double fresnel = fresnel_dielectric(i_h / std::sqrt(length2), eta_);
    if (fresnel >= 1.0) return 0.0;
    return std::abs(i_h) * std::abs(o_h) / (length2 * length2) * (1.0 - fresnel) * beckmann * scale_;
  }

 private:
  double inverse_sigma2_, z_i_, z_o_;
  double s_i_ = 0.0, s_o_ = 0.0, eta_ = 1.0, b_ = 1.0, scale_ = 0.0, h_z_ = 0.0, tilt_ = 0.0, cross_ = 0.0;
  bool reflection_ = false, absent_ = true;
};

}  // namespace skinlayer
