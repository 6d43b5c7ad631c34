// docs/model.md §22.3: OpenPBR's fuzz, Zeltner et al. 2022's LTC sheen.
#include "core/targets/zeltner_fuzz.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"

namespace skinlayer {
namespace {

double clamped_roughness(double roughness) { return std::clamp(roughness, 0.01, 1.0); }

}  // namespace

double zeltner_fuzz_albedo(double mu_o, double roughness) {
  const double r = clamped_roughness(roughness), x = std::clamp(mu_o, 0.0, 1.0);
  const double s = r * (0.0206607 + 1.58491 * r) / (0.0379424 + r * (1.32227 + r));
  const double m = r * (-0.193854 + r * (-1.14885 + r * (1.7932 - 0.95943 * r * r))) / (0.046391 + r);
  const double o = r * (0.000654023 + (-0.0207818 + 0.119681 * r) * r) / (1.26264 + r * (-1.92021 + r));
  const double z = (x - m) / s;
  return std::max(0.0, std::exp(-0.5 * z * z) / (s * std::sqrt(2.0 * kPi)) + o);  // the fit dips to -2e-5
}

double zeltner_ltc_distribution(double a, double b, const Vec3& omega_i, const Vec3& omega_o) {
  if (!(omega_i.z() > 0.0)) return 0.0;
  const double tangent = std::hypot(omega_o.x(), omega_o.y());
  const double cx = tangent > 0.0 ? omega_o.x() / tangent : 1.0, cy = tangent > 0.0 ? omega_o.y() / tangent : 0.0;
  const double lx = cx * omega_i.x() + cy * omega_i.y(), ly = -cy * omega_i.x() + cx * omega_i.y(), lz = omega_i.z();
  const double wx = a * lx + b * lz, wy = a * ly, wz = lz;
  const double length2 = wx * wx + wy * wy + wz * wz;
  return wz * kInvPi * (a / length2) * (a / length2);
}

double zeltner_fuzz_cosine_weighted(double roughness, const Vec3& omega_i, const Vec3& omega_o) {
  const double x = omega_o.z();
  if (!(omega_i.z() > 0.0 && x > 0.0)) return 0.0;
  const double r = clamped_roughness(roughness);
  const double a = (2.58126 * x + 0.813703 * r) * r / (1.0 + 0.310327 * x * x + 2.60994 * x * r);
  const double b = std::sqrt(std::max(0.0, 1.0 - x)) * (r - 1.0) * r * r * r /
                   (0.0000254053 + 1.71228 * x - 1.71506 * x * r + 1.34174 * r * r);
  return zeltner_fuzz_albedo(x, roughness) * zeltner_ltc_distribution(a, b, omega_i, omega_o);
}

}  // namespace skinlayer
