// The same stack seen from below: what light arriving from under the material meets, as a Material of its own, so
// that the solver that handles light from above handles light from below too.
//
// Indices: n_air above the top, n_1 .. n_L in the layers (top to bottom), n_below under the last. The flipped stack
// has the layers in reverse order, and
//   top    = the old bottom interface: eta' = n_L / n_below (the old bottom-eta; 1 over an index-matched bottom,
//            i.e. an open top), sigma' = the old bottom's sigma;
//   inner  = the interface above old layer i + 1 becomes the one below it: eta' = n_i / n_{i+1} = 1 / eta;
//   bottom = the old top, rough dielectric: eta' = n_1 / n_air (the old eta), sigma' = the old sigma.
// The flipped material's "air" is the old medium below (index n_below); its BSDFs are radiance BSDFs in that medium's
// frame, +z pointing down into the old medium below.
#pragma once

#include <optional>

#include "core/material.h"

namespace skinlayer {

// The material seen from below, or nullopt where no light from below reaches it: a Lambertian base or a
// semi-infinite last layer. The result is valid whenever the material is.
std::optional<Material> upside_down(const Material& material);

// n_below / n_above: the index under the whole stack relative to the air above it (n_1 / n_air times the interfaces'
// ratios over the bottom's eta; over an index-matched, Lambertian or semi-infinite bottom, the last layer's index).
double index_below_over_above(const Material& material);

}  // namespace skinlayer
