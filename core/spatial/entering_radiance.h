// The light that has entered through the top at the beam's point, as a function of its polar angle below the top
// (docs/model.md §21.15): what the unscattered and the once-scattered light leaving the bottom of a finite stack are
// built from, continuous in angle where the ordinates hold it only on their nodes.
//
// The ordinates carry the entering light as node radiance t_j (LateralTopInterface::source), or, under a smooth or
// open top at normal incidence, as a collimated beam. Light that crosses a finite stack without being scattered leaves
// its bottom at r = G tan(theta), G the stack's geometric depth: on the nodes that is a ring per node, where the walk
// and nature have a continuous spread. So, as the BSDF's unscattered light does (core/unscattered), the profile takes
// the entering radiance continuous in mu = cos(theta):
//   L(mu) = f_t(n, d(mu)) + interpolated(t_j - t_j,single)(mu)                                   [1/sr]
// with f_t the top's microfacet BTDF from the normal n into the direction d(mu) (a radiance BTDF, microfacet.h; the
// light per unit area is 1), and the rest of the node radiance. Under diffuse light that is all of it, linear in mu
// between the nodes and held beyond the end ones. Under a rough top of MicrofacetModel::Multiple it is the interface's
// multiply scattered lobe, which peaks along the normal, beyond the last node: its own shape at normal incidence
// (core/interfaces/multiple_scattering.h, clamped at 0), scaled to carry the nodes' flux of it:
//   rest(mu) = s f_ms,t(n -> d(mu)),   s = sum_j a_j mu_j (t_j - t_j,single) / int_0^1 f_ms,t(n -> d(mu)) mu d mu,
// the integral on the directions() below.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/interfaces/microfacet.h"
#include "core/interfaces/multiple_scattering.h"
#include "core/series/quadrature.h"
#include "core/spatial/lateral_top_interface.h"

namespace skinlayer {

class EnteringRadiance {
 public:
  // top: the ordinates' operators, built on `ordinates` nodes; rough: the top they were built from (nullopt for an open
  // or smooth top); its lobe is used at normal incidence, where top.source_single holds it on the nodes.
  EnteringRadiance(const LateralTopInterface& top, const std::optional<RoughDielectric>& rough, int ordinates);

  // L(mu) for a direction travelling down at cosine mu in (0, 1], uniform in azimuth: 1/sr per unit incident power.
  double operator()(double mu) const;
  // The collimated beam's flux below the top (LateralTopInterface::collimated): a direction of its own, mu = 1.
  double collimated() const { return collimated_; }
  // The entering light as directions: cosines mu_e and the power along each, 2 pi mu L(mu) d mu on Gauss-Legendre
  // panels in theta, closer where the refracted lobe is (the collimated beam not among them). Empty when no light
  // enters as radiance.
  const QuadratureRule& directions() const { return directions_; }
  // The angular width of the part that is a lobe (0 where none): panels in theta should be narrower than it.
  double lobe_width() const { return lobe_width_; }

 private:
  double multiple_transmission_from_normal(double mu) const;

  std::optional<RoughDielectric> lobe_;
  std::vector<double> nodes_, broad_;  // ascending cosines, and the broad part's radiance on them
  // The multiply scattered lobe's transmission from the normal and its scale s (none without one).
  std::shared_ptr<const MultipleScatteringLobe> multiple_;  // the top's (LateralTopInterface::multiple)
  double multiple_scale_ = 0.0;
  double collimated_ = 0.0, lobe_width_ = 0.0;
  QuadratureRule directions_;
};

}  // namespace skinlayer
