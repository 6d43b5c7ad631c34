// The bottom face of a finite stack as the ordinates of a lateral-frequency solve see it (docs/model.md §21.14,
// §21.17): what it sends back up, mode by mode, and what it lets out. Like the top it has no thickness and moves no
// light sideways, so it acts on each azimuthal mode at every frequency as it does in the BSDF solve, whose own
// operators these are (core/interfaces/layer_interfaces.h): a smooth (Fresnel) face, a rough dielectric one, or a
// Lambertian base.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "core/interfaces/microfacet.h"
#include "core/spatial/lateral_top_interface.h"

namespace skinlayer {

struct LateralBottomFace {
  // R23^m for m = 0 .. modes - 1 (N x N, dimensionless, quadrature weights included): downward node radiance at the
  // bottom to upward node radiance.
  std::vector<Eigen::MatrixXd> reflection;
  // The fraction of the flux meeting the face from inside along node j that leaves it (0 for a Lambertian base).
  Eigen::VectorXd exit;
};

// A smooth face, n_below / n_layer = eta: F(mu_j) on the diagonal of every mode (lateral_smooth_face).
LateralBottomFace smooth_bottom_face(double eta, int ordinates, int modes);

// A rough dielectric face (interface.eta = n_below / n_layer, in the frame +z up into the layer), projected on
// `azimuths` samples as the BSDF solve projects it. Throws std::invalid_argument for eta = 1 (no face).
LateralBottomFace rough_bottom_face(const RoughDielectric& interface, int ordinates, int modes, int azimuths = 97);

// A Lambertian base of albedo A in [0, 1]: mode 0 alone, 2 A mu_j a_j from every down node to every up node; it lets
// nothing out.
LateralBottomFace lambert_bottom_face(double albedo, int ordinates, int modes);

// The exit fraction X(mu) of a face for light meeting it from inside at any cosine mu in (0, 1], continuous in angle,
// for the transmitted light's closed forms (transmitted_low_orders.h): 1 - F(mu) for a smooth face, the rough face's
// directional transmittance (interface_albedo_parts_along, tabulated on 257 cosines and interpolated linearly: within
// 3e-5 of it for sigma >= 0.3, and 2e-4 at sigma 0.1, whose edge at the critical angle is sharper), 0 for a
// Lambertian base, 1 where there is no face.
using ExitFraction = std::function<double(double mu)>;
ExitFraction smooth_exit_fraction(double eta);
ExitFraction rough_exit_fraction(const RoughDielectric& interface);

}  // namespace skinlayer
