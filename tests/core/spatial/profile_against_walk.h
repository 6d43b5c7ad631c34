// The spatial profile against the Monte Carlo reference's exit positions, annulus by annulus: within 2% of the
// walk's value, or 3 of its standard errors, in every annulus where the profile exceeds 1e-3 of its peak (the issue's
// criterion), for reflection and a slab's transmission; the total within 4 standard errors. 10^6 paths.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/material.h"
#include "core/reference/monte_carlo.h"
#include "core/spatial/layer_profile.h"

namespace skinlayer::test {

// The resolution the profile tests check: 12 nodes, 16 modes, 40 frequencies (the command's).
inline LayerProfileOptions profile_test_options() {
  LayerProfileOptions options;
  options.resolution = {12, 16};
  options.frequencies = 40;
  return options;
}

// Light that enters spread over directions and leaves a finite stack's bottom: on 24 nodes, as the command takes it
// (docs/model.md §21.15).
inline LayerProfileOptions transmitted_radiance_options() {
  LayerProfileOptions options = profile_test_options();
  options.resolution.ordinates = 24;
  return options;
}

// `material` is `layer` as the walk takes it. With mu_t (the first layer's extinction, 1/mm) the edges are in mm,
// as the walk tallies a stack whose layers all have their lengths, and the profile's values become 1/mm^2.
inline void expect_profile_matches_the_walk(const ProfileLayer& layer, const Material& material,
                                            const LayerProfileOptions& profile_options,
                                            const std::vector<double>& edges, double mu_t = 1.0) {
  std::vector<double> in_mfp;
  for (const double r : edges) in_mfp.push_back(r * mu_t);
  LayerProfile profile = layer_profile(layer, in_mfp, profile_options);
  for (double& v : profile.reflectance) v *= mu_t * mu_t;
  for (double& v : profile.transmittance) v *= mu_t * mu_t;
  const double tau = layer.slabs().back().tau;  // the last slab: a stack ending in a half-space transmits nothing
  std::vector<RadialBin> bins;
  for (const ExitSide side : {ExitSide::Reflected, ExitSide::Transmitted}) {
    for (std::size_t i = 0; i + 1 < edges.size(); ++i) bins.push_back({side, edges[i], edges[i + 1]});
  }
  MonteCarloOptions options;
  options.paths = 1'000'000;
  options.seed = 11;
  const MonteCarloResult mc = simulate_layer(material, 0.0, {}, options, bins);
  std::printf("  total  profile %.5f  walk %.5f +- %.1e\n", profile.total_reflectance, mc.reflectance_subsurface.value,
              mc.reflectance_subsurface.standard_error);
  EXPECT_NEAR(profile.total_reflectance, mc.reflectance_subsurface.value,
              4.0 * mc.reflectance_subsurface.standard_error);
  const std::size_t annuli = edges.size() - 1;
  for (const ExitSide side : {ExitSide::Reflected, ExitSide::Transmitted}) {
    const std::vector<double>& values = side == ExitSide::Reflected ? profile.reflectance : profile.transmittance;
    if (std::isinf(tau) && side == ExitSide::Transmitted) continue;
    double peak = 0.0;
    for (const double v : values) peak = std::max(peak, v);
    for (std::size_t i = 0; i < annuli; ++i) {
      const MonteCarloEstimate& walk = mc.radial_bins[(side == ExitSide::Reflected ? 0 : annuli) + i];
      const double diff = values[i] - walk.value;
      std::printf("  %s [%5.2f, %5.2f)  profile %.4e  walk %.4e +- %.1e  (%+.2f%%, %+.2f SE)\n",
                  side == ExitSide::Reflected ? "R" : "T", edges[i], edges[i + 1], values[i], walk.value,
                  walk.standard_error, 100.0 * diff / walk.value, diff / walk.standard_error);
      if (values[i] < 1e-3 * peak) continue;
      EXPECT_TRUE(std::abs(diff) <= 0.02 * walk.value || std::abs(diff) <= 3.0 * walk.standard_error)
          << (side == ExitSide::Reflected ? "R" : "T") << " annulus [" << edges[i] << ", " << edges[i + 1]
          << "): profile " << values[i] << ", walk " << walk.value << " +- " << walk.standard_error;
    }
  }
}

}  // namespace skinlayer::test
