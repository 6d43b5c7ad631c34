// Light scattered exactly once in an open layer (no interfaces, normal incidence), where it leaves: the singular part
// of the spatial profile, in closed form (docs/model.md §21.6). Lengths are in mean free paths.
//
// A unit-power pencil beam enters at the origin and travels down; the part scattered at depth z (density e^-z) into
// direction theta leaves the top at r = z tan(theta), after a path z / cos(theta), or the bottom of a slab of depth
// tau_b at r = (tau_b - z) tan(theta), after (tau_b - z) / cos(theta). With p the Henyey-Greenstein phase function:
//   power through the annulus [r0, r1) = Omega int_0^{tau_b} e^-z int_{theta(r0)}^{theta(r1)} p e^{-d / cos theta}
//                                        2 pi sin(theta) d theta dz,   d = z (top) or tau_b - z (bottom),
//   and its Hankel transform  F1(k) = 2 pi Omega int_0^1 p(-+mu) int_0^{tau_b} e^-z e^{-d/mu} J0(k d tan theta) dz dmu.
#pragma once

namespace skinlayer {

enum class LayerFace { Top, Bottom };

// The singly scattered power leaving `face` through the annulus r0 <= r < r1 (mean free paths), per unit incident
// power. tau may be +infinity for the top.
double single_scattered_power(double tau, double albedo, double g, LayerFace face, double r0, double r1);

// The same light per unit area at radius r > 0 (1/mfp^2): with l = sqrt(r^2 + d^2),
//   R1(r) = Omega int_0^{tau_b} e^-z p(-+d/l) e^-l d / l^3 dz.
// It grows like 1/r as r -> 0.
double single_scattered_density(double tau, double albedo, double g, LayerFace face, double r);

// Its Hankel transform at spatial frequency k (1 / mean free path): F1(0) is the singly scattered reflectance or
// transmittance.
double single_scattered_transform(double tau, double albedo, double g, LayerFace face, double k);

}  // namespace skinlayer
