#include "app/render/unscattered_plane.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "app/process/parallel_for.h"
#include "core/conventions.h"

namespace skinlayer {
namespace {

// A quarter of the narrowest refracted lobe's width (refracted_lobe_width, core/interfaces/microfacet.h).
double lobe_scale(const UnscatteredLight& light) {
  double w = 1.0;
  if (light.path() != UnscatteredPath::BottomOnly) w = std::min(w, refracted_lobe_width(light.top()));
  if (light.path() != UnscatteredPath::TopOnly) w = std::min(w, refracted_lobe_width(light.bottom()));
  return std::clamp(0.25 * w, 1e-3, 0.1);
}

}  // namespace

UnscatteredPlane sample_unscattered_plane(const UnscatteredLight& light, double theta_i, int samples,
                                          const UnscatteredPlane* previous) {
  const std::size_t count =
      light.path() == UnscatteredPath::None || samples < 2 ? 0 : static_cast<std::size_t>(samples);
  if (previous != nullptr && previous->btdf.size() == count && previous->theta_i == theta_i) {
    if (previous->light == light) return *previous;
    if (previous->terms && previous->light.at_depth(light.tau()) == light) {
      UnscatteredPlane plane = *previous;  // the same directions: only their attenuation changes
      plane.light = light;
      for (std::size_t k = 0; k < count; ++k) {
        plane.btdf[k] = static_cast<float>(sum_depth_terms((*plane.terms)[k], light.tau()));
      }
      return plane;
    }
  }
  UnscatteredPlane plane;
  plane.light = light;
  plane.theta_i = theta_i;
  if (count == 0) return plane;
  plane.centre = light.straight_through_angle(theta_i);
  plane.scale = lobe_scale(light);
  plane.u_min = std::asinh((-0.5 * kPi - plane.centre) / plane.scale);
  plane.u_max = std::asinh((0.5 * kPi - plane.centre) / plane.scale);
  plane.btdf.resize(count);
  auto terms = std::make_shared<std::vector<std::vector<DepthTerm>>>(count);
  constexpr int kChunk = 16;  // samples per task
  parallel_for_threads((samples + kChunk - 1) / kChunk, [&](int chunk) {
    for (int k = chunk * kChunk; k < std::min(samples, (chunk + 1) * kChunk); ++k) {
      const auto index = static_cast<std::size_t>(k);
      const double s = unscattered_plane_angle(plane, index);
      (*terms)[index] = light.btdf_terms(theta_i, std::abs(s), s >= 0.0 ? kPi : 0.0);
      plane.btdf[index] = static_cast<float>(sum_depth_terms((*terms)[index], light.tau()));
    }
  });
  plane.terms = std::move(terms);
  return plane;
}

double unscattered_plane_angle(const UnscatteredPlane& plane, std::size_t k) {
  const double n = static_cast<double>(plane.btdf.size());
  const double u = plane.u_min + (plane.u_max - plane.u_min) * static_cast<double>(k) / (n - 1.0);
  return std::clamp(plane.centre + plane.scale * std::sinh(u), -0.5 * kPi, 0.5 * kPi);
}

double unscattered_plane_value(const UnscatteredPlane& plane, double signed_theta_o) {
  const int n = static_cast<int>(plane.btdf.size());
  if (n < 2) return 0.0;
  const double u = std::asinh((signed_theta_o - plane.centre) / plane.scale);
  const double x = std::clamp((u - plane.u_min) / (plane.u_max - plane.u_min), 0.0, 1.0) * (n - 1);
  const int cell = std::min(static_cast<int>(x), n - 2);
  const double t = x - cell;
  return (1.0 - t) * plane.btdf[static_cast<std::size_t>(cell)] + t * plane.btdf[static_cast<std::size_t>(cell) + 1];
}

}  // namespace skinlayer
