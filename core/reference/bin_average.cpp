#include "core/reference/bin_average.h"

#include <cmath>

#include "core/solver.h"

namespace skinlayer {

namespace {

// The midpoint rule of the bin on a grid x grid lattice in (theta, phi), weighted by cos theta sin theta.
template <typename F>
double midpoint_average(const AngularBin& bin, int grid, F f) {
  double sum = 0.0, weight_sum = 0.0;
  for (int a = 0; a < grid; ++a) {
    const double theta = bin.theta_min + (a + 0.5) * (bin.theta_max - bin.theta_min) / grid;
    const double weight = std::cos(theta) * std::sin(theta);  // cos theta d omega / (dtheta dphi)
    for (int b = 0; b < grid; ++b) {
      const double phi = bin.phi_min + (b + 0.5) * (bin.phi_max - bin.phi_min) / grid;
      sum += weight * f(theta, phi);
      weight_sum += weight;
    }
  }
  return sum / weight_sum;
}

}  // namespace

double layer_bsdf_bin_average(const Material& material, const LayerTables& tables, double theta_i,
                              const AngularBin& bin, int grid) {
  const bool reflected = bin.side == ExitSide::Reflected;
  const double smooth = midpoint_average(bin, grid, [&](double theta, double phi) {
    return reflected ? tables.brdf_scattered(theta_i, theta, phi) + brdf_surface(material, theta_i, theta, phi)
                     : tables.btdf_scattered(theta_i, theta, phi);
  });
  // The unscattered part's lobes can be a degree wide: a finer lattice for them, four times as fine where the part
  // is a closed form, twice where it is a quadrature of its own (two interfaces).
  const UnscatteredLight& light = tables.unscattered();
  if (reflected ? !light.reflects() : light.path() == UnscatteredPath::None) return smooth;
  const int fine = (light.path() == UnscatteredPath::TopThenBottom ? 2 : 4) * grid;
  return smooth + midpoint_average(bin, fine, [&](double theta, double phi) {
           return reflected ? light.brdf(theta_i, theta, phi) : light.btdf(theta_i, theta, phi);
         });
}

}  // namespace skinlayer
