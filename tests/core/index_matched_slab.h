// The layer that the reference tables, closed forms and spatial profiles describe: no interface at the top (eta 1)
// and an index-matched half-space below (nothing reflects at either face).
#pragma once

#include "core/material.h"

namespace skinlayer::test {

inline Material index_matched_slab(double tau, double albedo, double g) {
  Material m;
  m.eta = 1.0;
  m.bottom.kind = BottomKind::Matched;
  m.tau = tau;
  m.albedo = albedo;
  m.g = g;
  return m;
}

}  // namespace skinlayer::test
