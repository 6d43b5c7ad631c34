// The light a rough dielectric interface scatters more than once on its microsurface (MicrofacetModel::Multiple;
// Heitz, Hanika, d'Eon & Dachsbacher 2016), as an azimuthally uniform BSDF of the incident and exit cosines: its
// Fourier mode 0. Read from core/data/microfacet_multiple_scattering.csv, which the microsurface random walk
// (core/reference/microsurface_walk.h) wrote through tests/generators/microfacet_multiple_scattering.cpp: for each
// Beckmann sigma, relative index e = n_beyond / n_incident and incident polar angle (2.5 to 87.5 degrees in steps of
// 5), the multiply scattered light's azimuthally averaged BSDF in exit bins 5 degrees wide centred on the same angles,
// back to the incident side and beyond.
//
// For one interface the table is interpolated linearly in sigma and in ln e (e = eta from above, 1/eta from below),
// then, per evaluation, by Catmull-Rom in the incident and the exit polar angle between the grid's angles (the end
// angles' values held beyond them, the result held at 0 or above).
// What it returns is made reciprocal: the reflection symmetric in (mu_i, mu_o), the transmission with its radiance
// scaling, f_t(above mu_i -> below mu_o) = eta^2 f_t(below mu_o -> above mu_i) (eta = n_below / n_above), each the
// mean of the table's two estimates. Its magnitude carries Monte Carlo noise (30,000-200,000 walks a row, about 1% of
// the multiply scattered energy), so the solver takes from it the shape and the split between reflection and
// transmission, and the energy from the exact single-scattering albedos: from a direction of cosine mu the multiply
// scattered light is
//   l(mu) = 1 - R_single(mu) - T_single(mu)   (the height-correlated single scattering's loss, interface_albedo.h),
// of which the share s(mu) (this table's, on its grid, linear in angle between) is transmitted. The interface
// operators match each node's lobe to that energy (core/interfaces/interface_operators.h); what this class returns
// at a pair of directions is the table's lobe as it is. All values are in 1/sr, not cosine-weighted; the cosines
// are from the normal of each direction's own side.
#pragma once

#include <array>
#include <vector>

#include "core/interfaces/microfacet.h"

namespace skinlayer {

// Whether the interface keeps a multiply scattered lobe: under MicrofacetModel::Multiple, where there is an interface
// at all (eta != 1). Under Single, and at eta = 1, every part of the solver leaves the lobe out.
inline bool has_multiple_scattering(const RoughDielectric& interface) {
  return interface.microfacet == MicrofacetModel::Multiple && interface.eta != 1.0;
}

class MultipleScatteringLobe {
 public:
  // The lobe of `interface` (its microfacet model is not consulted: this is the Multiple model's part). eta = 1 (no
  // interface) gives a lobe that is zero everywhere.
  explicit MultipleScatteringLobe(const RoughDielectric& interface);

  // Light from above (from_above) or below at cosine mu_i, leaving at cosine mu_o on its own side (reflection) or
  // beyond (transmission); cosines in [0, 1].
  double reflection(bool from_above, double mu_i, double mu_o) const;
  double transmission(bool from_above, double mu_i, double mu_o) const;

  // The transmitted share of the multiply scattered light from that side at mu_i: T / (R + T) of the rows above,
  // in [0, 1] (1/2 where the table holds nothing).
  double transmitted_share(bool from_above, double mu_i) const;

 private:
  // One side's table at this interface's sigma and index: [incident node][exit bin], and the shares at the nodes.
  struct Side {
    std::vector<std::vector<double>> reflection, transmission;  // [incident angle][exit angle], on the grid
    std::vector<double> share;                                  // per incident angle
  };
  double raw(const Side& side, bool reflect, double mu_i, double mu_o) const;
  // The grid's interpolation at a cosine: the node below and the weight of the next one (polar angles ascending).
  std::pair<std::size_t, double> node(double mu) const;
  double raw_reflection(bool from_above, double mu_i, double mu_o) const;
  double raw_transmission(bool from_above, double mu_i, double mu_o) const;

  double eta_ = 1.0;
  std::vector<double> angles_;  // the grid's polar angles, radians, ascending
  std::array<Side, 2> sides_;   // [0] from above, [1] from below
};

}  // namespace skinlayer
