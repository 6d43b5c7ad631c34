// Layers under a rough top for the profile tests: the material the walk and the solver take, and the ProfileLayer
// the profile takes for it (its top, the layers below in the first one's mean free paths, the interfaces between
// them).
#pragma once

#include <optional>

#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/spatial/layer_profile.h"
#include "tests/core/index_matched_slab.h"

namespace skinlayer::test {

// A layer of optical depth tau (+infinity: a half-space) under a top of eta 1.4 and Beckmann sigma, over an
// index-matched bottom.
inline Material rough_top_layer(double tau, double sigma, double albedo, double g) {
  Material m = index_matched_slab(tau, albedo, g);
  m.eta = 1.4;
  m.sigma = sigma;
  return m;
}

// The layers below relate their lengths through mu_t (all of them have it, or none, then each is taken as the first's).
inline ProfileLayer as_profile_layer(const Material& m) {
  ProfileLayer layer{m.tau, m.albedo, m.g};
  layer.top = top_interface(m);
  for (const StackedLayer& below : m.below) {
    const double relative = below.extinction && m.extinction ? *below.extinction / *m.extinction : 1.0;
    layer.below.push_back(LateralSlab{below.tau, below.albedo, below.g, relative});
    const bool face = below.interface && below.interface->eta != 1.0;
    layer.faces.push_back(
        face ? std::optional(RoughDielectric{below.interface->eta, below.interface->sigma, m.microfacet})
             : std::nullopt);
  }
  return layer;
}

}  // namespace skinlayer::test
