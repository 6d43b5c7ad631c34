#include "core/interfaces/multiple_scattering.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"
#include "core/interfaces/multiple_scattering_energy.h"
#include "core/interfaces/multiple_scattering_table.h"
#include "core/series/log_linear_azimuth_series.h"

namespace skinlayer {
namespace {

constexpr auto kAngles = static_cast<std::size_t>(MultipleScatteringSamples::kAngles);
// The floor of every shape f / sqrt(l_i l_o): a uniform lobe, which carries kShapeFloor * pi of the loss.
constexpr double kShapeFloor = 1e-4 / kPi;

Eigen::MatrixXd zeros(std::size_t rows, std::size_t columns) {
  return Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(columns));
}

// A kernel's samples upside down: (i, o) -> (o, i), scaled.
Eigen::MatrixXd swapped(const Eigen::MatrixXd& samples, double scale) {
  Eigen::MatrixXd result(samples.rows(), samples.cols());
  for (std::size_t i = 0; i < kAngles; ++i) {
    for (std::size_t o = 0; o < kAngles; ++o) {
      result.row(static_cast<Eigen::Index>(o * kAngles + i)) =
          scale * samples.row(static_cast<Eigen::Index>(i * kAngles + o));
    }
  }
  return result;
}

}  // namespace

MultipleScatteringLobe::MultipleScatteringLobe(const RoughDielectric& interface, int modes)
    : interface_(interface), eta_(interface.eta) {
  if (interface.eta == 1.0 || modes <= 0) return;
  for (std::size_t k = 0; k < kAngles; ++k) {
    angles_.push_back(degrees_to_radians(MultipleScatteringSamples::kAngleStep * static_cast<double>(k)));
  }
  // In the table's frame (E = n_below / n_above >= 1): the shapes, their series, and their energies matched.
  const bool flipped = interface.eta < 1.0;  // the table's interface upside down
  const double index = flipped ? 1.0 / interface.eta : interface.eta;
  MultipleScatteringShape shape = multiple_scattering_shape(interface.sigma, index);
  azimuths_ = shape.shapes.azimuths;
  modes_ = static_cast<std::size_t>(modes);
  series_.emplace(azimuths_, modes);
  std::array<Eigen::MatrixXd, 3> coefficients, mode_zero, scale;
  // A floor under every shape, a lobe uniform in angle carrying about 1e-4 of the light: where the walk met the
  // microsurface again too rarely to draw a lobe (small sigma near the normal), the light still has somewhere to go,
  // and every pair of directions that both lose light is coupled, so the symmetric matching below always has its
  // solution.
  for (Eigen::MatrixXd& kernel : shape.shapes.kernels) kernel.array() += kShapeFloor;
  for (std::size_t kernel = 0; kernel < 3; ++kernel) {
    // Every mode of a pair's shape in one pass of its series; the reflections are reciprocal, so their pairs (i, o)
    // with o < i are copies of (o, i).
    const bool reciprocal = kernel != kTransmissionDown;
    Eigen::MatrixXd samples = shape.shapes.kernels[kernel];
    for (std::size_t i = 0; reciprocal && i < kAngles; ++i) {
      for (std::size_t o = 0; o < i; ++o) samples.row(static_cast<Eigen::Index>(i * kAngles + o)).setZero();
    }
    coefficients[kernel] = series_->coefficients(samples);  // (angles^2) x modes
    for (std::size_t i = 0; reciprocal && i < kAngles; ++i) {
      for (std::size_t o = 0; o < i; ++o) {
        coefficients[kernel].row(static_cast<Eigen::Index>(i * kAngles + o)) =
            coefficients[kernel].row(static_cast<Eigen::Index>(o * kAngles + i));
      }
    }
    // The lobe is sqrt(l_i l_o) times its shape, each loss on its direction's own side.
    const auto& incident = kernel == kReflectionBelow ? shape.loss_below : shape.loss_above;
    const auto& exit = kernel == kReflectionAbove ? shape.loss_above : shape.loss_below;
    scale[kernel] = Eigen::MatrixXd(static_cast<Eigen::Index>(kAngles), static_cast<Eigen::Index>(kAngles));
    for (std::size_t i = 0; i < kAngles; ++i) {
      for (std::size_t o = 0; o < kAngles; ++o) {
        scale[kernel](static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(o)) = std::sqrt(incident[i] * exit[o]);
      }
    }
    mode_zero[kernel] = multiple_scattering_grid(coefficients[kernel].col(0)).cwiseMax(0.0).cwiseProduct(scale[kernel]);
  }
  const std::array<Eigen::MatrixXd, 3> matched =
      multiple_scattering_energy_scales(mode_zero, shape.loss_above, shape.loss_below, index);
  for (std::size_t kernel = 0; kernel < 3; ++kernel) {
    scale[kernel] = scale[kernel].cwiseProduct(matched[kernel]);
    for (std::size_t i = 0; i < kAngles; ++i) {
      for (std::size_t o = 0; o < kAngles; ++o) {
        const auto row = static_cast<Eigen::Index>(i * kAngles + o);
        const double factor = scale[kernel](static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(o));
        shape.shapes.kernels[kernel].row(row) *= factor;
        coefficients[kernel].row(row) *= factor;
      }
    }
    // The reflections' samples symmetric too, so that the lobe itself (value_at), not only its modes, is
    // reciprocal: the pairs (i, o) with o < i are copies of (o, i), whose modes the coefficients already are.
    for (std::size_t i = 0; kernel != kTransmissionDown && i < kAngles; ++i) {
      for (std::size_t o = 0; o < i; ++o) {
        shape.shapes.kernels[kernel].row(static_cast<Eigen::Index>(i * kAngles + o)) =
            shape.shapes.kernels[kernel].row(static_cast<Eigen::Index>(o * kAngles + i));
        coefficients[kernel].row(static_cast<Eigen::Index>(i * kAngles + o)) =
            coefficients[kernel].row(static_cast<Eigen::Index>(o * kAngles + i));
      }
    }
  }
  // This interface's kernels: the table's, or upside down (reflections swapped, the transmission the table's from
  // below, its transpose / E^2).
  const std::array<std::size_t, 3> from =
      flipped ? std::array<std::size_t, 3>{kReflectionBelow, kReflectionAbove, kTransmissionDown}
              : std::array<std::size_t, 3>{kReflectionAbove, kReflectionBelow, kTransmissionDown};
  for (std::size_t kernel = 0; kernel < 3; ++kernel) {
    const bool swap = flipped && kernel == kTransmissionDown;
    const double factor = swap ? 1.0 / (index * index) : 1.0;
    samples_[kernel] = swap ? swapped(shape.shapes.kernels[from[kernel]], factor) : shape.shapes.kernels[from[kernel]];
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> by_rows = samples_[kernel];
    rows_[kernel].assign(by_rows.data(), by_rows.data() + by_rows.size());
    const Eigen::MatrixXd& c = coefficients[from[kernel]];
    for (std::size_t m = 0; m < modes_; ++m) {
      Eigen::MatrixXd mode = multiple_scattering_grid(c.col(static_cast<Eigen::Index>(m)));
      modes_of_[kernel].push_back(swap ? Eigen::MatrixXd(factor * mode.transpose()) : mode);
    }
  }
  // The energies from each grid angle: the exact integral of mode 0's polar interpolant.
  const std::array<double, MultipleScatteringSamples::kAngles>& quadrature = polar_grid_quadrature();
  const Eigen::Map<const Eigen::VectorXd> energy(quadrature.data(), static_cast<Eigen::Index>(kAngles));
  const Eigen::MatrixXd& down = modes_of_[kTransmissionDown].front();
  reflected_ = {modes_of_[kReflectionAbove].front().cwiseMax(0.0) * energy,
                modes_of_[kReflectionBelow].front().cwiseMax(0.0) * energy};
  transmitted_ = {down.cwiseMax(0.0) * energy, down.transpose().cwiseMax(0.0) * energy / (eta_ * eta_)};
}

namespace {

// W_i K W_o^T for the polar interpolation's weight matrices W (four terms a row): the rows of K interpolated to the
// exit cosines, then those to the incident ones, four terms per entry each.
Eigen::MatrixXd interpolated(const Eigen::MatrixXd& kernel, std::span<const double> mu_i,
                             std::span<const double> mu_o) {
  const auto exits = static_cast<Eigen::Index>(mu_o.size());
  Eigen::MatrixXd to_exits = Eigen::MatrixXd::Zero(kernel.rows(), exits);
  for (Eigen::Index b = 0; b < exits; ++b) {
    const PolarStencil s = polar_grid_stencil(mu_o[static_cast<std::size_t>(b)]);
    for (std::size_t q = 0; q < 4; ++q) to_exits.col(b) += s.weight[q] * kernel.col(s.index[q]);
  }
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(mu_i.size()), exits);
  for (Eigen::Index a = 0; a < result.rows(); ++a) {
    const PolarStencil s = polar_grid_stencil(mu_i[static_cast<std::size_t>(a)]);
    for (std::size_t p = 0; p < 4; ++p) result.row(a) += s.weight[p] * to_exits.row(s.index[p]);
  }
  return result;
}

}  // namespace

Eigen::MatrixXd MultipleScatteringLobe::reflection_modes(bool from_above, int m, std::span<const double> mu_i,
                                                         std::span<const double> mu_o) const {
  if (m >= modes()) return zeros(mu_i.size(), mu_o.size());
  const Eigen::MatrixXd& kernel =
      modes_of_[from_above ? kReflectionAbove : kReflectionBelow][static_cast<std::size_t>(m)];
  Eigen::MatrixXd f = interpolated(kernel, mu_i, mu_o);
  if (m == 0) f = f.cwiseMax(0.0);  // a cubic can overshoot below zero beside a steep rise
  return f;
}

Eigen::MatrixXd MultipleScatteringLobe::transmission_modes(bool from_above, int m, std::span<const double> mu_i,
                                                           std::span<const double> mu_o) const {
  if (m >= modes()) return zeros(mu_i.size(), mu_o.size());
  if (!from_above) return transmission_modes(true, m, mu_o, mu_i).transpose() / (eta_ * eta_);
  Eigen::MatrixXd f = interpolated(modes_of_[kTransmissionDown][static_cast<std::size_t>(m)], mu_i, mu_o);
  if (m == 0) f = f.cwiseMax(0.0);
  return f;
}

double MultipleScatteringLobe::reflection(bool from_above, int m, double mu_i, double mu_o) const {
  // Both orders, so that the value is symmetric to the last bit.
  const auto one = [&](double a, double b) {
    return reflection_modes(from_above, m, std::span<const double>(&a, 1), std::span<const double>(&b, 1))(0, 0);
  };
  return 0.5 * (one(mu_i, mu_o) + one(mu_o, mu_i));
}

double MultipleScatteringLobe::transmission(bool from_above, int m, double mu_i, double mu_o) const {
  return transmission_modes(from_above, m, std::span<const double>(&mu_i, 1), std::span<const double>(&mu_o, 1))(0, 0);
}

double MultipleScatteringLobe::value_at(Kernel kernel, double mu_i, double mu_o, double phi) const {
  const PolarStencil si = polar_grid_stencil(mu_i), so = polar_grid_stencil(mu_o);
  const LogLinearAzimuthSeries::Position at = series_->locate(phi);
  const std::size_t samples = azimuths_.size();
  double sum = 0.0;
  for (std::size_t p = 0; p < 4; ++p) {
    for (std::size_t q = 0; q < 4; ++q) {
      const double w = si.weight[p] * so.weight[q];
      if (w == 0.0) continue;
      const std::size_t row = static_cast<std::size_t>(si.index[p]) * kAngles + static_cast<std::size_t>(so.index[q]);
      sum += w * series_->value(&rows_[kernel][row * samples], at);
    }
  }
  return sum;
}

double MultipleScatteringLobe::reflection_at(bool from_above, double mu_i, double mu_o, double phi) const {
  if (modes_ == 0) return 0.0;
  // Symmetric samples and one polar rule for both cosines: reciprocal, up to the order of the sum.
  return value_at(from_above ? kReflectionAbove : kReflectionBelow, mu_i, mu_o, phi);
}

double MultipleScatteringLobe::transmission_at(bool from_above, double mu_i, double mu_o, double phi) const {
  if (modes_ == 0) return 0.0;
  if (!from_above) return transmission_at(true, mu_o, mu_i, phi) / (eta_ * eta_);
  return value_at(kTransmissionDown, mu_i, mu_o, phi);
}

const Eigen::MatrixXd& MultipleScatteringLobe::reflection_samples(bool from_above) const {
  return samples_[from_above ? kReflectionAbove : kReflectionBelow];
}

double MultipleScatteringLobe::transmitted_share(bool from_above, double mu_i) const {
  const double reflected = energy(from_above, true, mu_i), transmitted = energy(from_above, false, mu_i);
  return reflected + transmitted > 0.0 ? std::clamp(transmitted / (reflected + transmitted), 0.0, 1.0) : 0.5;
}

double MultipleScatteringLobe::energy(bool from_above, bool reflected, double mu_i) const {
  if (modes_ == 0) return 0.0;
  const Eigen::VectorXd& energies = (reflected ? reflected_ : transmitted_)[from_above ? 0 : 1];
  const auto w = polar_grid_weights(mu_i);
  return std::max(0.0,
                  Eigen::Map<const Eigen::RowVectorXd>(w.data(), static_cast<Eigen::Index>(w.size())).dot(energies));
}

MultipleScatteringReflectionSeries::MultipleScatteringReflectionSeries(const MultipleScatteringLobe& lobe,
                                                                       bool from_above, int modes) {
  if (lobe.modes() == 0 || modes <= 0) return;
  coefficients_ = LogLinearAzimuthSeries(lobe.azimuths(), modes).coefficients(lobe.reflection_samples(from_above));
}

void MultipleScatteringReflectionSeries::add_to(std::vector<double>& series, double mu_i, double mu_o,
                                                double scale) const {
  if (coefficients_.size() == 0) return;
  if (series.size() < static_cast<std::size_t>(modes())) series.resize(static_cast<std::size_t>(modes()), 0.0);
  const PolarStencil si = polar_grid_stencil(mu_i), so = polar_grid_stencil(mu_o);
  Eigen::Map<Eigen::RowVectorXd> out(series.data(), modes());
  for (std::size_t p = 0; p < 4; ++p) {
    for (std::size_t q = 0; q < 4; ++q) {
      const double w = scale * si.weight[p] * so.weight[q];
      if (w == 0.0) continue;
      out += w * coefficients_.row(static_cast<Eigen::Index>(static_cast<std::size_t>(si.index[p]) * kAngles +
                                                             static_cast<std::size_t>(so.index[q])));
    }
  }
}

std::optional<MultipleScatteringLobe> multiple_scattering_lobe(const RoughDielectric& interface, int modes) {
  if (!has_multiple_scattering(interface)) return std::nullopt;
  return MultipleScatteringLobe(interface, modes);
}

}  // namespace skinlayer
