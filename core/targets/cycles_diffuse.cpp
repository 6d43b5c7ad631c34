// docs/model.md §22.1.1: Cycles' Principled diffuse, Lambert or its energy-preserving Oren-Nayar.
#include "core/targets/cycles_diffuse.h"

#include <algorithm>

#include "core/conventions.h"
#include "core/targets/eon_diffuse.h"

namespace skinlayer {
namespace {

// m(rho) above, bsdf_oren_nayar_setup's colour factor (the colour saturated to [0, 1]).
Rgb multiple_scattering_albedo(const Rgb& rho, double average) {
  const Rgb albedo = rho.min(1.0).max(0.0);
  return albedo.square() * average / (1.0 - albedo * (1.0 - average));
}

}  // namespace

Rgb cycles_diffuse_cosine_weighted(const Rgb& rho, double roughness, const Vec3& omega_i, const Vec3& omega_o) {
  const double mu_i = omega_i.z(), mu_o = omega_o.z();
  if (!(mu_i > 0.0 && mu_o > 0.0)) return Rgb::Zero();
  if (roughness < kCyclesLambertBelow) return rho * mu_i * kInvPi;
  // EON's white lobe is f_FON + the white multiple scattering, whose m(1) = 1: take the latter out to get f_FON.
  const double average = eon_average_single_scattering_albedo(roughness);
  const double multiple = mu_i * (1.0 - eon_single_scattering_albedo(mu_i, roughness)) *
                          (1.0 - eon_single_scattering_albedo(mu_o, roughness)) / (kPi * (1.0 - average));
  const double single = eon_diffuse_cosine_weighted(Rgb::Ones(), roughness, omega_i, omega_o)(0) - multiple;
  return rho * (single + multiple_scattering_albedo(rho, average) * multiple);
}

Rgb cycles_diffuse_albedo(const Rgb& rho, double roughness, double mu_o) {
  if (roughness < kCyclesLambertBelow) return rho;
  const double single = eon_single_scattering_albedo(mu_o, roughness);
  return rho *
         (single + multiple_scattering_albedo(rho, eon_average_single_scattering_albedo(roughness)) * (1.0 - single));
}

}  // namespace skinlayer
