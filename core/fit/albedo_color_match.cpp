#include "core/fit/albedo_color_match.h"

#include "core/solve/solve_cache.h"
#include "core/solver.h"

namespace skinlayer {
namespace {

// Normal-incidence reflectance of the material with the top albedo `albedo`.
double reflectance_at_normal(const Material& material, double albedo, const SolveOptions& options) {
  const double theta[] = {0.0};
  const double albedos[] = {albedo};
  return directional_albedo(material, theta, albedos, options).front().front().reflectance();
}

}  // namespace

AlbedoColorMatch match_top_albedo(const std::array<Material, 3>& channels, const std::array<double, 3>& target,
                                  const SolveOptions& options) {
  constexpr int kSteps = 40;  // 2^-40 of the albedo range
  SolveCache own_cache;
  SolveOptions cached = options;
  if (cached.cache == nullptr) cached.cache = &own_cache;
  const auto normal_reflectance = [&cached](const Material& material, double albedo) {
    return reflectance_at_normal(material, albedo, cached);
  };
  AlbedoColorMatch match;
  for (std::size_t c = 0; c < 3; ++c) {
    const Material& material = channels[c];
    double lo = 0.0, hi = 1.0;
    const double at_lo = normal_reflectance(material, lo), at_hi = normal_reflectance(material, hi);
    match.solves += 2;
    if (target[c] <= at_lo) {
      match.albedo[c] = lo;
      match.reflectance[c] = at_lo;
      continue;
    }
    if (target[c] >= at_hi) {
      match.albedo[c] = hi;
      match.reflectance[c] = at_hi;
      continue;
    }
    for (int step = 0; step < kSteps; ++step) {
      const double mid = 0.5 * (lo + hi);
      (normal_reflectance(material, mid) < target[c] ? lo : hi) = mid;
      ++match.solves;
    }
    match.albedo[c] = 0.5 * (lo + hi);
    match.reflectance[c] = normal_reflectance(material, match.albedo[c]);
    ++match.solves;
  }
  return match;
}

}  // namespace skinlayer
