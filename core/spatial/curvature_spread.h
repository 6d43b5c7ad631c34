// The subsurface light of a sphere lit by a distant light, spread over the sphere by the material's spatial profile:
// the profile pre-integrated over the sphere's curvature (docs/model.md §21.13), as a function of the angle theta
// between the surface normal and the light.
//
// Light entering at x' with irradiance E cos+(n'.l) leaves at x with the profile R(d) of their chord distance d. The
// spread irradiance at x, normalised by the kernel's own integral over the sphere,
//   D(theta) = int R(|x - x'|) cos+(n'.l) dA' / int R(|x - x'|) dA',
// replaces cos+(theta) under the subsurface term. It tends to cos+(theta) when the profile is narrow against the
// sphere, reaches past the terminator (theta > 90 degrees) when it is not, and keeps the light: the normalised
// kernel is the same at every x, so int D dA = int cos+ dA over the sphere (pi rho^2 of 4 pi rho^2).
//
// The profile comes as powers per annulus of chord distance, spread evenly over the sphere's band at those
// distances. Over the band between the geodesic angles a0 and a1 (d = 2 rho sin(a / 2)), the azimuth's integral is
// closed-form: int_0^{2 pi} cos+(a + b cos(beta)) d beta with a = cos(alpha) cos(theta), b = sin(alpha) sin(theta)
// is 2 pi a for a >= b, 0 for a <= -b, else 2 (a acos(-a/b) + sqrt(b^2 - a^2)); alpha is taken by Gauss-Legendre.
#pragma once

#include <span>
#include <vector>

namespace skinlayer {

// edges: annulus edges in chord distance, increasing from 0 (any length unit); powers[i]: the light leaving through
// [edges[i], edges[i + 1]) per unit incident power (its sum need not be 1); sphere_radius in the same unit, > 0.
// Annuli beyond the sphere's diameter are cut there, and their light beyond it dropped (the rest is renormalised).
// Throws std::invalid_argument for bad edges, powers (negative, or all zero within the diameter) or radius.
class CurvatureSpread {
 public:
  CurvatureSpread(std::span<const double> edges, std::span<const double> powers, double sphere_radius);
  // D(theta) for theta in [0, pi] (radians from the light).
  double operator()(double theta) const;
  // D at theta_k = pi k / (count - 1), k = 0 .. count - 1: the texture the sphere shader reads.
  std::vector<double> sampled(int count) const;

 private:
  struct Band {
    double weight;                      // the annulus's share of the power
    std::vector<double> alpha, factor;  // Gauss nodes in the geodesic angle, sin(alpha) w / (2 pi band area)
  };
  std::vector<Band> bands_;
};

}  // namespace skinlayer
