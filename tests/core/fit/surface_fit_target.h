// A fit target made by a shader model itself (a surface with brdf_cosine_weighted and albedo(mu_o)): its f cos on
// fit_pairs() and its albedo at 0, 0.5, 1 and 1.3 radians, for the fits' tests that find a model's own parameters.
#pragma once

#include <cmath>

#include "core/fit/brdf_fit_target.h"

namespace skinlayer::test {

template <typename Surface>
BrdfFitTarget target_of(const Surface& truth) {
  BrdfFitTarget target;
  target.pairs = fit_pairs();
  for (const DirectionPair& pair : target.pairs) {
    target.brdf_cosine.push_back(truth.brdf_cosine_weighted(pair.omega_i, pair.omega_o));
  }
  for (const double angle : {0.0, 0.5, 1.0, 1.3}) {
    target.albedo_angles.push_back(angle);
    target.albedo.push_back(truth.albedo(std::cos(angle)));
  }
  return target;
}

}  // namespace skinlayer::test
