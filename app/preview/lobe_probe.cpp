#include "app/preview/lobe_probe.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "core/solver.h"

namespace skinlayer {

LobeSample probe_lobe(const ColorTables& tables, double theta_i, double x, double y) {
  LobeSample sample;
  sample.reflection = y >= 0.0;
  sample.theta_o = std::atan2(std::abs(x), std::abs(y));
  sample.phi = x >= 0.0 ? kPi : 0.0;
  if (sample.reflection) sample.surface = brdf_surface(tables.material.layer, theta_i, sample.theta_o, sample.phi);
  for (int c = 0; c < 3; ++c) {
    sample.total[c] = sample.reflection ? brdf_total(tables, c, theta_i, sample.theta_o, sample.phi)
                                        : btdf_total(tables, c, theta_i, sample.theta_o, sample.phi);
  }
  return sample;
}

double lobe_radius(const LobeView& view, double f) {
  if (!(f > 0.0)) return 0.0;
  if (view.log_scale) return std::max(0.0, 1.0 + std::log10(f / view.peak) / view.decades);
  return f / view.peak;
}

double lobe_value_at_radius(const LobeView& view, double r) {
  if (view.log_scale) return view.peak * std::pow(10.0, (r - 1.0) * view.decades);
  return r * view.peak;
}

}  // namespace skinlayer
