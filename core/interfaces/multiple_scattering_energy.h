// The energy of a tabulated multiply scattered lobe (core/interfaces/multiple_scattering_table.h), matched to the light
// that single scattering leaves: from every grid angle on either side, l(mu) = 1 - R_single(mu) - T_single(mu) (the
// height-correlated single scattering's loss, core/interfaces/interface_albedo.h), all of which meets the
// microsurface again and leaves it at last (Heitz et al. 2016). The energy a kernel carries from a grid angle is the
// hemisphere integral of its mode 0 (the azimuthal mean of its interpolant in azimuth) as the lobe interpolates it in
// the exit angle (polar_grid_quadrature), so it is exact for the lobe as evaluated.
//
// The light from above is split as the lobe splits it: the transmission from each incident angle is scaled alike
// (its row times l / (R + T)) and keeps its share s = T / (R + T); the reflection carries the rest, l (1 - s), by a
// symmetric (Sinkhorn-Knopp) scaling f(i, o) -> d_i f(i, o) d_o that keeps it reciprocal. From below, the
// transmission is the scaled one from above by reciprocity, f_t(below i -> above o) = f_t(above o -> below i) / E^2,
// and the reflection carries what it leaves, l - T_below, by the same symmetric scaling. So every grid angle keeps
// all of its light on both sides, and the lobe stays reciprocal.
#pragma once

#include <Eigen/Core>
#include <array>
#include <span>

#include "core/interfaces/multiple_scattering_table.h"

namespace skinlayer {

// A kernel's mode 0 on the grid (the mean over azimuth of each pair's interpolant; incident rows, exit columns), and
// a column of values per pair (row i * kAngles + o) as that grid.
Eigen::MatrixXd multiple_scattering_mode_zero(const Eigen::MatrixXd& kernel, std::span<const double> azimuths);
Eigen::MatrixXd multiple_scattering_grid(const Eigen::VectorXd& pairs);

// The scales that match a lobe of index E = n_below / n_above to the losses at its grid angles from above and from
// below (as above), from each kernel's mode 0 on the grid (incident rows, exit columns): per kernel, the factor of
// each pair (i, o) of grid angles, by which all its samples and modes are multiplied. A grid angle from which a
// kernel carries nothing, or should carry nothing, keeps a factor 1.
std::array<Eigen::MatrixXd, 3> multiple_scattering_energy_scales(const std::array<Eigen::MatrixXd, 3>& mode_zero,
                                                                 std::span<const double> loss_above,
                                                                 std::span<const double> loss_below, double index);

// Those scales applied to the lobe's samples (mode 0 from them: the mean over azimuth of their interpolant).
void match_multiple_scattering_energy(MultipleScatteringSamples& lobe, std::span<const double> loss_above,
                                      std::span<const double> loss_below, double index);

}  // namespace skinlayer
