// Layers under a rough top for the profile tests: the material the walk and the solver take (the profile takes it
// through profile_layer).
#pragma once

#include "core/material.h"
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

}  // namespace skinlayer::test
