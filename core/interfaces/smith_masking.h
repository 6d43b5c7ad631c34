// Smith masking-shadowing of two directions at one microfacet, from each direction's own masking G1 = 1 / (1 +
// Lambda) (microfacet.h: smith_g1_beckmann), for the two microfacet models (microfacet_model.h).
//
// Single (Stam 2001; Walter et al. 2007): the separable form, as if the two were independent:
//   G2 = G1(wi) G1(wo)   in reflection and in transmission.
// Multiple (Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", height-correlated
// form): a point is visible from w with probability C1(h)^Lambda(w) at its height h, C1 the heights' cumulative, and
// integrating over heights (u = C1(h) uniform) gives, whatever the height distribution,
//   reflection:    G2 = int_0^1 u^Lambda_i u^Lambda_o du = 1 / (1 + Lambda_i + Lambda_o),
//   transmission:  G2 = int_0^1 u^Lambda_i (1 - u)^Lambda_o du = B(1 + Lambda_i, 1 + Lambda_o),
// with B the Beta function and each Lambda of its direction seen from its own side. It is what a random walk on the
// microsurface does in one meeting (core/reference/microsurface_walk.h). Against the separable form it keeps more
// reflection (a point seen from two directions on one side is likely high) and less transmission (a point seen
// from above is likely high, one seen from below likely low).
#pragma once

#include "core/interfaces/microfacet_model.h"

namespace skinlayer {

// Dimensionless, in [0, 1]; 0 when either G1 is 0. g1_i and g1_o are the macro-surface G1 of the two directions.
double smith_g2_reflection(double g1_i, double g1_o, MicrofacetModel model);
double smith_g2_transmission(double g1_i, double g1_o, MicrofacetModel model);

}  // namespace skinlayer
