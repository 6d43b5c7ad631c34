// A rough top interface as the discrete ordinates of a lateral-frequency solve see it, for a pencil beam at normal
// incidence or a diffusely lit point (docs/model.md §21.9, §21.12). These are the BSDF solve's own operators
// (core/interfaces/layer_interfaces.h), on the same nodes and energy-matched the same way, so that the k = 0 response
// is the BSDF's subsurface reflectance.
//
// The interface has no thickness: it moves no light sideways, so in k-space it acts on each azimuthal mode as it does
// in the BSDF, R21^m mapping the upward node radiance of mode m to the downward one, whatever the frequency.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "core/interfaces/microfacet.h"
#include "core/interfaces/multiple_scattering.h"
#include "core/series/quadrature.h"

namespace skinlayer {

// How the light arrives at the entry point: a collimated beam along the normal, or diffuse light (radiance 1/pi from
// every direction of the upper hemisphere, unit power in all).
enum class Incidence { Normal, Diffuse };

struct LateralTopInterface {
  // R21^m for m = 0 .. modes - 1 (N x N, dimensionless, quadrature weights included): upward node radiance at the
  // top to downward node radiance.
  std::vector<Eigen::MatrixXd> reflection;
  // t12: the downward node radiance that light of unit power per unit area leaves below the interface (1/sr). At
  // normal incidence, and averaged over diffuse incidence, it is uniform in azimuth: mode 0 alone.
  Eigen::VectorXd source;
  // The part of `source` that the top's microfacet single scattering puts there, at normal incidence under a rough
  // top (its lobe is known in closed form: microfacet_btdf); empty elsewhere.
  Eigen::VectorXd source_single;
  // T_top,inside(mu_j): the fraction of the flux meeting the interface from inside along node j that leaves it.
  Eigen::VectorXd exit;
  // The interface's own multiply scattered reflection of the beam (under MicrofacetModel::Multiple, else 0): it leaves
  // at the entry point, so it is in the BSDF's subsurface reflectance but not in the spatial profile.
  double surface_multiple_reflectance = 0.0;
  // The interface's multiply scattered lobe the operators were built from (null under MicrofacetModel::Single).
  std::shared_ptr<const MultipleScatteringLobe> multiple;
  // Under a smooth top the normal beam stays collimated inside: its flux there, 1 - F(1). 0 where the light enters as
  // node radiance (`source`).
  double collimated = 0.0;
};

// A smooth (Fresnel) face of the stack, as the ordinates see it (§21.14): specular reflection keeps the direction of
// travel's azimuth, so every mode reflects alike, node radiance times F(mu_j); the rest, 1 - F(mu_j), crosses.
// eta: the index across the face over the layer's (n_above / n_layer for the top seen from inside, n_below / n_layer
// for the bottom).
struct LateralSmoothFace {
  Eigen::VectorXd reflection;  // F(mu_j) for light meeting the face from inside along node j
  Eigen::VectorXd exit;        // 1 - F(mu_j)
};
LateralSmoothFace lateral_smooth_face(double eta, int ordinates);

// A smooth top of relative index eta = n_layer / n_above > 0, at normal incidence: reflection F(mu_j) inside, no node
// source, the beam collimated with flux 1 - F(1). The specular reflection outside is no part of a profile.
LateralTopInterface smooth_top_interface(double eta, int ordinates, int modes);

// The top's operators on `ordinates` double-Gauss nodes per hemisphere and `modes` cosine modes, projected on
// `azimuths` samples of [0, pi] as the BSDF solve projects them. Diffuse incidence averages the source and the
// surface's reflection over diffuse_incidence_cosines(). Throws std::invalid_argument for eta = 1 (no interface:
// the open layer's collimated beam, or open_top_diffuse_interface).
LateralTopInterface lateral_top_interface(const RoughDielectric& top, int ordinates, int modes,
                                          Incidence incidence = Incidence::Normal, int azimuths = 97);

// No interface, as the ordinates see it: nothing reflected, everything leaving. The normal beam stays collimated
// (collimated = 1); diffuse light is held as node radiance, 1/pi on every down node (unit power on the double-Gauss
// nodes, whose sum of a_j mu_j is 1/2).
LateralTopInterface open_top_interface(int ordinates, int modes, Incidence incidence);

// The incident cosines over which diffuse incidence averages, with weights 2 mu w (Gauss-Legendre on (0, 1), 24
// nodes): the quantity at diffuse incidence is sum_q weight_q X(mu_q), the hemispherical average of X.
QuadratureRule diffuse_incidence_cosines();

}  // namespace skinlayer
