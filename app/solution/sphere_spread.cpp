#include "app/solution/sphere_spread.h"

#include <cmath>
#include <stdexcept>

#include "app/solution/document_profile.h"
#include "core/conventions.h"
#include "core/material.h"
#include "core/spatial/curvature_spread.h"

namespace skinlayer {
namespace {

std::vector<double> spread_edges() {
  std::vector<double> edges = {0.0};
  for (int i = 0; i < 64; ++i) edges.push_back(0.002 * std::pow(1e4, i / 63.0));  // 2 um to 20 mm
  return edges;
}

}  // namespace

SpreadProfile spread_profile(const MaterialDocument& document, bool preview, const ParallelFor& parallel_for) {
  if (!document.skin && !document.layer.extinction) {  // a skin's layers have theirs; a stack's are checked below
    throw ParameterError(
        "sphere radius: the material has no length, so its light cannot spread over a sphere in mm (give --mu-t, "
        "1/mm)");
  }
  ProfileRequest request;
  request.options.resolution = {8, 12};
  request.options.frequencies = 32;
  request.options.parallel_for = parallel_for;
  request.options.reflectance_only = true;  // the sphere shows the light leaving its surface
  request.preview = preview;
  SpreadProfile profile;
  profile.edges_mm = spread_edges();
  const DocumentProfile values = document_profile_in_annuli(document, profile.edges_mm, request);
  for (std::size_t c = 0; c < 3; ++c) {
    const std::vector<double>& channel = values.reflectance[values.reflectance.size() == 1 ? 0 : c];
    std::vector<double> power;
    for (std::size_t i = 0; i < channel.size(); ++i) {
      const double r0 = profile.edges_mm[i], r1 = profile.edges_mm[i + 1];
      power.push_back(std::max(0.0, channel[i]) * kPi * (r1 * r1 - r0 * r0));
    }
    profile.power.push_back(std::move(power));
    profile.per_area.push_back(channel);
  }
  return profile;
}

std::vector<float> spread_texture(const SpreadProfile& profile, double sphere_radius_mm, int samples) {
  std::vector<float> texels(static_cast<std::size_t>(3 * samples), 0.0f);
  for (std::size_t c = 0; c < 3; ++c) {
    const std::vector<double> values =
        CurvatureSpread(profile.edges_mm, profile.power[c], sphere_radius_mm).sampled(samples);
    for (int k = 0; k < samples; ++k) texels[static_cast<std::size_t>(3 * k) + c] = static_cast<float>(values[k]);
  }
  return texels;
}

}  // namespace skinlayer
