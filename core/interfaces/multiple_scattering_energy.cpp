#include "core/interfaces/multiple_scattering_energy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/series/log_linear_azimuth_series.h"

namespace skinlayer {
namespace {

constexpr auto kAngles = static_cast<Eigen::Index>(MultipleScatteringSamples::kAngles);
constexpr int kMaxSteps = 500;
constexpr double kTolerance = 1e-12;

Eigen::VectorXd exit_quadrature() {
  const auto& q = polar_grid_quadrature();
  return Eigen::Map<const Eigen::VectorXd>(q.data(), kAngles);
}

// The symmetric scaling d with d_i sum_o q_o f0(i, o) d_o = target_i, iterated as d_i <- sqrt(d_i target_i /
// energy_i) to a relative residual of 1e-12 or 500 steps (d = 1 where a row or its target is 0).
Eigen::VectorXd symmetric_scaling(const Eigen::MatrixXd& f0, const Eigen::VectorXd& q, std::span<const double> target) {
  const Eigen::MatrixXd weighted = f0 * q.asDiagonal();  // (i, o): f0(i, o) q_o
  const Eigen::VectorXd base = weighted.rowwise().sum();
  Eigen::VectorXd d = Eigen::VectorXd::Ones(kAngles), best = d;
  double least = std::numeric_limits<double>::infinity();
  for (int step = 0; step < kMaxSteps; ++step) {
    const Eigen::VectorXd energy = d.cwiseProduct(weighted * d);
    double residual = 0.0;
    Eigen::VectorXd next = d;
    for (Eigen::Index i = 0; i < kAngles; ++i) {
      const double wanted = target[static_cast<std::size_t>(i)];
      if (!(base(i) > 0.0 && wanted > 0.0)) continue;
      residual = std::max(residual, std::abs(energy(i) / wanted - 1.0));
      next(i) *= std::sqrt(wanted / energy(i));
    }
    // Kept: the best finite scaling so far (a kernel too sparse to carry its targets, which the shapes' floor
    // prevents, would otherwise run off).
    if (residual < least) {
      least = residual;
      best = d;
    }
    if (residual < kTolerance || !next.allFinite()) break;
    d = next;
  }
  return best;
}

}  // namespace

Eigen::MatrixXd multiple_scattering_mode_zero(const Eigen::MatrixXd& kernel, std::span<const double> azimuths) {
  return multiple_scattering_grid(LogLinearAzimuthSeries(azimuths, 1).coefficients(kernel.cwiseMax(0.0)).col(0));
}

Eigen::MatrixXd multiple_scattering_grid(const Eigen::VectorXd& pairs) {
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(pairs.data(), kAngles,
                                                                                                  kAngles);
}

std::array<Eigen::MatrixXd, 3> multiple_scattering_energy_scales(const std::array<Eigen::MatrixXd, 3>& mode_zero,
                                                                 std::span<const double> loss_above,
                                                                 std::span<const double> loss_below, double index) {
  enum { kReflectionAbove = 0, kReflectionBelow = 1, kTransmissionDown = 2 };
  const Eigen::VectorXd q = exit_quadrature();
  // From above: the transmission keeps its share of l.
  const Eigen::VectorXd carried = mode_zero[kReflectionAbove] * q + mode_zero[kTransmissionDown] * q;
  Eigen::VectorXd share = Eigen::VectorXd::Ones(kAngles);
  for (Eigen::Index i = 0; i < kAngles; ++i) {
    const double loss = loss_above[static_cast<std::size_t>(i)];
    if (carried(i) > 0.0 && loss > 0.0) share(i) = loss / carried(i);
  }
  const Eigen::MatrixXd transmitted = share.asDiagonal() * mode_zero[kTransmissionDown];
  // The reflections carry the rest, from above and (after the transmission up that reciprocity implies) from below.
  const Eigen::VectorXd down = transmitted * q, up = transmitted.transpose() * q / (index * index);
  std::vector<double> rest_above(static_cast<std::size_t>(kAngles)), rest_below(static_cast<std::size_t>(kAngles));
  for (std::size_t i = 0; i < rest_above.size(); ++i) {
    const auto at = static_cast<Eigen::Index>(i);
    rest_above[i] = std::max(0.0, loss_above[i] - down(at));
    rest_below[i] = std::max(0.0, loss_below[i] - up(at));
  }
  const Eigen::VectorXd d_above = symmetric_scaling(mode_zero[kReflectionAbove], q, rest_above);
  const Eigen::VectorXd d_below = symmetric_scaling(mode_zero[kReflectionBelow], q, rest_below);
  return {d_above * d_above.transpose(), d_below * d_below.transpose(), share * Eigen::RowVectorXd::Ones(kAngles)};
}

void match_multiple_scattering_energy(MultipleScatteringSamples& lobe, std::span<const double> loss_above,
                                      std::span<const double> loss_below, double index) {
  std::array<Eigen::MatrixXd, 3> mode_zero;
  for (std::size_t k = 0; k < 3; ++k) mode_zero[k] = multiple_scattering_mode_zero(lobe.kernels[k], lobe.azimuths);
  const std::array<Eigen::MatrixXd, 3> scales =
      multiple_scattering_energy_scales(mode_zero, loss_above, loss_below, index);
  for (std::size_t k = 0; k < 3; ++k) {
    for (Eigen::Index i = 0; i < kAngles; ++i) {
      for (Eigen::Index o = 0; o < kAngles; ++o) lobe.kernels[k].row(i * kAngles + o) *= scales[k](i, o);
    }
  }
}

}  // namespace skinlayer
