#include "core/color/ciede2000.h"

#include <Eigen/LU>
#include <cmath>

#include "core/color/spectral_color.h"
#include "core/conventions.h"

namespace skinlayer {
namespace {

// CIE 1976's f(t): the cube root above (6/29)^3, a line below it.
double lab_f(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

double degrees(double radians) { return radians * 180.0 / kPi; }
double radians(double degrees) { return degrees * kPi / 180.0; }

}  // namespace

Eigen::Vector3d xyz_to_lab(const Eigen::Vector3d& xyz, const Eigen::Vector3d& white) {
  const double fx = lab_f(xyz.x() / white.x()), fy = lab_f(xyz.y() / white.y()), fz = lab_f(xyz.z() / white.z());
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

Eigen::Vector3d linear_srgb_to_lab(const Eigen::Vector3d& rgb) {
  return xyz_to_lab(xyz_to_linear_srgb().inverse() * rgb, d65_white_xyz());
}

double ciede2000(const Eigen::Vector3d& lab1, const Eigen::Vector3d& lab2) {
  const double l1 = lab1.x(), a1 = lab1.y(), b1 = lab1.z();
  const double l2 = lab2.x(), a2 = lab2.y(), b2 = lab2.z();
  // a' = (1 + G) a, with G from the mean chroma (Sharma et al. eqs. 2-5).
  const double c_mean = 0.5 * (std::hypot(a1, b1) + std::hypot(a2, b2));
  const double c7 = std::pow(c_mean, 7.0);
  const double g = 0.5 * (1.0 - std::sqrt(c7 / (c7 + std::pow(25.0, 7.0))));
  const double a1p = (1.0 + g) * a1, a2p = (1.0 + g) * a2;
  const double c1p = std::hypot(a1p, b1), c2p = std::hypot(a2p, b2);
  const auto hue = [](double b, double ap) {
    if (b == 0.0 && ap == 0.0) return 0.0;
    const double h = degrees(std::atan2(b, ap));
    return h < 0.0 ? h + 360.0 : h;
  };
  const double h1p = hue(b1, a1p), h2p = hue(b2, a2p);
  // Differences (eqs. 8-11).
  const double dl = l2 - l1, dc = c2p - c1p;
  double dh = 0.0;
  if (c1p * c2p != 0.0) {
    dh = h2p - h1p;
    if (dh > 180.0) dh -= 360.0;
    if (dh < -180.0) dh += 360.0;
  }
  const double d_big_h = 2.0 * std::sqrt(c1p * c2p) * std::sin(radians(dh / 2.0));
  // Means and weights (eqs. 12-22).
  const double l_mean = 0.5 * (l1 + l2), cp_mean = 0.5 * (c1p + c2p);
  double h_mean = h1p + h2p;
  if (c1p * c2p != 0.0) {
    if (std::abs(h1p - h2p) <= 180.0) {
      h_mean /= 2.0;
    } else {
      h_mean = h_mean < 360.0 ? (h_mean + 360.0) / 2.0 : (h_mean - 360.0) / 2.0;
    }
  }
  const double t = 1.0 - 0.17 * std::cos(radians(h_mean - 30.0)) + 0.24 * std::cos(radians(2.0 * h_mean)) +
                   0.32 * std::cos(radians(3.0 * h_mean + 6.0)) - 0.20 * std::cos(radians(4.0 * h_mean - 63.0));
  const double d_theta = 30.0 * std::exp(-std::pow((h_mean - 275.0) / 25.0, 2.0));
  const double cp7 = std::pow(cp_mean, 7.0);
  const double r_c = 2.0 * std::sqrt(cp7 / (cp7 + std::pow(25.0, 7.0)));
  const double l50 = (l_mean - 50.0) * (l_mean - 50.0);
  const double s_l = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
  const double s_c = 1.0 + 0.045 * cp_mean;
  const double s_h = 1.0 + 0.015 * cp_mean * t;
  const double r_t = -std::sin(radians(2.0 * d_theta)) * r_c;
  const double tl = dl / s_l, tc = dc / s_c, th = d_big_h / s_h;
  return std::sqrt(tl * tl + tc * tc + th * th + r_t * tc * th);
}

}  // namespace skinlayer
