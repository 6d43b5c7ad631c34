// The light a rough dielectric interface scatters more than once on its microsurface (MicrofacetModel::Multiple;
// Heitz, Hanika, d'Eon & Dachsbacher 2016), as the Fourier series of its BSDF in azimuth, mode by mode: the
// microsurface random walk's own lobe, tabulated (core/interfaces/multiple_scattering_table.h) at polar angles 5
// degrees apart and at azimuths closest at the forward plane, where it is as sharp as a specular lobe.
//
// For one interface the table is interpolated to its sigma and index; an interface of eta < 1 is the table's of
// E = 1/eta seen upside down: its reflections swap, and its transmission from above is the table's from below,
// f_t(below i -> above o) = f_t(above o -> below i) / E^2. At each pair of the table's polar angles the lobe is
// exponential in azimuth between the table's azimuths (linear where a sample is zero), and its modes are that
// function's exact cosine series (core/series/log_linear_azimuth_series.h), in graphics convention (phi = phi_o -
// phi_i, pi forward; core/conventions.h):
//   f(theta_i, theta_o, phi) = sum_m f^m(theta_i, theta_o) cos(m phi)   [1/sr, not cosine-weighted].
// Between the polar angles the lobe, and each mode with it, is Catmull-Rom in angle. Reflection stays symmetric in
// (mu_i, mu_o) and transmission obeys f_t(above mu_i -> below mu_o) = eta^2 f_t(below mu_o -> above mu_i) (eta =
// n_below / n_above), mode by mode, as the table does.
//
// Its energy: from every grid angle on either side the lobe carries exactly the light single scattering loses there,
//   l(mu) = 1 - R_single(mu) - T_single(mu)   (the height-correlated single scattering's loss, interface_albedo.h),
// as the loss table has it (interpolated like the shapes), split between reflection and transmission as the walk
// splits it (core/interfaces/multiple_scattering_energy.h); between grid angles its energy is the grid's, interpolated
// as the lobe is. The solver matches each interface operator to the exact albedos at its own directions, every mode
// alike (core/interfaces/interface_operators.h). Cosines are from the normal of each direction's own side.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "core/interfaces/microfacet.h"
#include "core/series/log_linear_azimuth_series.h"

namespace skinlayer {

// Whether an interface keeps a multiply scattered lobe: under MicrofacetModel::Multiple, where there is an interface
// at all (eta != 1). Under Single, and at eta = 1, every part of the solver leaves the lobe out.
inline bool has_multiple_scattering(const RoughDielectric& interface) {
  return interface.microfacet == MicrofacetModel::Multiple && interface.eta != 1.0;
}

class MultipleScatteringLobe {
 public:
  // The first `modes` Fourier modes of the lobe of `interface` (its microfacet model is not consulted: this is the
  // Multiple model's part). eta = 1 (no interface) gives a lobe without modes.
  MultipleScatteringLobe(const RoughDielectric& interface, int modes);

  // The number of Fourier modes the lobe holds (0 without an interface).
  int modes() const { return static_cast<int>(modes_); }
  const RoughDielectric& interface() const { return interface_; }

  // Mode m of the light from above (from_above) or below at cosine mu_i, leaving at cosine mu_o on its own side
  // (reflection) or beyond (transmission); cosines in [0, 1]; 0 for m >= modes().
  double reflection(bool from_above, int m, double mu_i, double mu_o) const;
  double transmission(bool from_above, int m, double mu_i, double mu_o) const;
  // The same between sets of cosines (their signs ignored): a (mu_i x mu_o) matrix, one product of the polar
  // interpolation's weights with the mode's kernel on the grid.
  Eigen::MatrixXd reflection_modes(bool from_above, int m, std::span<const double> mu_i,
                                   std::span<const double> mu_o) const;
  Eigen::MatrixXd transmission_modes(bool from_above, int m, std::span<const double> mu_i,
                                     std::span<const double> mu_o) const;

  // The lobe itself at a pair of directions (phi in graphics convention), which its modes are the exact series of; 0
  // without an interface. Beside a steep rise (small sigma, both directions near grazing) the polar interpolation can
  // dip below zero, by up to a few parts in 1e4 of the lobe's peak; a caller that needs a BSDF value clamps it at 0
  // (core/unscattered/unscattered_light.h).
  double reflection_at(bool from_above, double mu_i, double mu_o, double phi) const;
  double transmission_at(bool from_above, double mu_i, double mu_o, double phi) const;

  // The reflection from one side as the lobe holds it, for a renderer that evaluates it as reflection_at does: at
  // the grid's angles (5 degrees apart from the normal, MultipleScatteringSamples), row i * angles + o (symmetric),
  // one column per azimuth of azimuths() (radians, ascending on [0, pi]), 1/sr. Empty without an interface.
  const Eigen::MatrixXd& reflection_samples(bool from_above) const;
  const std::vector<double>& azimuths() const { return azimuths_; }

  // The transmitted share of the multiply scattered light from that side at mu_i: T / (R + T) of mode 0, in [0, 1]
  // (1/2 where the table holds nothing).
  double transmitted_share(bool from_above, double mu_i) const;
  // The energy the lobe carries from that side at mu_i, reflected or transmitted: the hemisphere integral of its
  // mode 0, exact for its polar interpolant (the energies at the grid angles, interpolated as the lobe is).
  double energy(bool from_above, bool reflected, double mu_i) const;

 private:
  enum Kernel { kReflectionAbove = 0, kReflectionBelow = 1, kTransmissionDown = 2 };
  // The kernel at (mu_i, mu_o, phi): each grid pair's function of azimuth, weighted as the polar interpolation weighs
  // it.
  double value_at(Kernel kernel, double mu_i, double mu_o, double phi) const;

  RoughDielectric interface_{};
  double eta_ = 1.0;
  std::size_t modes_ = 0;
  std::vector<double> angles_;    // the grid's polar angles, radians, ascending
  std::vector<double> azimuths_;  // the samples' azimuths, radians, ascending on [0, pi]
  std::optional<LogLinearAzimuthSeries> series_;
  // This interface's kernels: per kernel, at the grid's (theta_i, theta_o), row i * angles + o, one column per
  // azimuth sample; and per kernel and mode, incident grid angles x exit grid angles. 1/sr.
  std::array<Eigen::MatrixXd, 3> samples_;
  std::array<std::vector<double>, 3> rows_;  // the same samples row by row, for value_at
  std::array<std::vector<Eigen::MatrixXd>, 3> modes_of_;
  // Per incident grid angle, the reflected and transmitted energies (mode 0's hemisphere integral), [from above,
  // from below].
  std::array<Eigen::VectorXd, 2> reflected_, transmitted_;
};

// The reflection of a lobe from one side as a Fourier series of many modes at any pair of cosines, for exports,
// where a grazing lobe wants hundreds: each grid pair's series computed once (the exact cosine series of its samples,
// LogLinearAzimuthSeries), and the pairs weighted as the polar interpolation weighs them, which is exact for
// reflection_at, unclamped:  f(mu_i, mu_o, phi) = sum_m c_m cos(m phi)   [1/sr, graphics convention].
class MultipleScatteringReflectionSeries {
 public:
  MultipleScatteringReflectionSeries(const MultipleScatteringLobe& lobe, bool from_above, int modes);
  // c_0 ... c_{modes - 1} at the pair, times `scale`, added into `series` (grown to `modes` if shorter).
  void add_to(std::vector<double>& series, double mu_i, double mu_o, double scale) const;
  int modes() const { return static_cast<int>(coefficients_.cols()); }

 private:
  Eigen::MatrixXd coefficients_;  // per grid pair (row i * angles + o), its modes
};

// The interface's lobe with `modes` modes, or none where it keeps no multiply scattered light
// (has_multiple_scattering).
std::optional<MultipleScatteringLobe> multiple_scattering_lobe(const RoughDielectric& interface, int modes);

}  // namespace skinlayer
