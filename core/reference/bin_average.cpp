#include "core/reference/bin_average.h"

#include <cmath>

#include "core/solver.h"

namespace skinlayer {

double layer_bsdf_bin_average(const Material& material, const LayerTables& tables, double theta_i,
                              const AngularBin& bin, int grid) {
  double sum = 0.0, weight_sum = 0.0;
  for (int a = 0; a < grid; ++a) {
    const double theta = bin.theta_min + (a + 0.5) * (bin.theta_max - bin.theta_min) / grid;
    const double weight = std::cos(theta) * std::sin(theta);  // cos theta d omega / (dtheta dphi)
    for (int b = 0; b < grid; ++b) {
      const double phi = bin.phi_min + (b + 0.5) * (bin.phi_max - bin.phi_min) / grid;
      const double f = bin.side == ExitSide::Reflected
                           ? tables.brdf_subsurface(theta_i, theta, phi) + brdf_surface(material, theta_i, theta, phi)
                           : tables.btdf(theta_i, theta, phi);
      sum += weight * f;
      weight_sum += weight;
    }
  }
  return sum / weight_sum;
}

}  // namespace skinlayer
