// The adding equations of one Fourier mode on the discrete ordinates: two layers, each described by its node
// operators, combined into the operators of the pair (van de Hulst 1980; Hansen & Travis 1974, eq. 123-125). The
// multiple reflections between the layers sum to (I - R R')^-1, solved, never inverted explicitly.
//
// Layer a above layer b, each with reflection seen from above (R) and below (R*), transmission downward (T) and
// upward (T*), all N x N on node radiances:
//   R_ab  = R_a + T*_a (I - R_b R*_a)^-1 R_b T_a
//   T_ab  = T_b (I - R*_a R_b)^-1 T_a
//   R*_ab = R*_b + T_b (I - R*_a R_b)^-1 R*_a T*_b
//   T*_ab = T*_a (I - R_b R*_a)^-1 T*_b
// A layer that reflects but transmits nothing (a semi-infinite slab, a Lambertian base, the whole stack below)
// has T = T* = 0: then R_ab is the reflection of a over that base, as a boundary solve with R_bottom = R_b gives.
#pragma once

#include <Eigen/Core>

#include "core/medium/slab_operators.h"

namespace skinlayer {

// Both directions of a layer; a homogeneous slab has from_below == from_above.
struct LayerPair {
  LayerOperators from_above;  // R, T for light arriving from above
  LayerOperators from_below;  // R*, T* for light arriving from below
};

LayerPair symmetric_layer(const LayerOperators& operators);

// a above b.
LayerPair add_layers(const LayerPair& a, const LayerPair& b);

// The reflection from above of `a` over a base that only reflects (its reflection from above `base`).
Eigen::MatrixXd reflection_over(const LayerPair& a, const Eigen::MatrixXd& base);

}  // namespace skinlayer
