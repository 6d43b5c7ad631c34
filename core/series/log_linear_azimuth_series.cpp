#include "core/series/log_linear_azimuth_series.h"

#include <algorithm>
#include <cmath>

#include "core/conventions.h"

namespace skinlayer {
namespace {

// A segment's logarithmic slope times its width, ln(f_b / f_a), below which it is taken as flat.
constexpr double kFlat = 1e-9;
// A segment whose values are both below this share of the function's peak adds nothing (at most 1e-9 of the peak
// to any coefficient): a sharp lobe's far tail costs no work.
constexpr double kNegligible = 1e-9;

}  // namespace

LogLinearAzimuthSeries::LogLinearAzimuthSeries(std::span<const double> azimuths, int modes)
    : azimuths_(azimuths.begin(), azimuths.end()), modes_(static_cast<std::size_t>(std::max(modes, 0))) {
  cos_.resize(azimuths_.size() * modes_);
  sin_.resize(azimuths_.size() * modes_);
  for (std::size_t k = 0; k < azimuths_.size(); ++k) {
    for (std::size_t m = 0; m < modes_; ++m) {
      cos_[k * modes_ + m] = std::cos(static_cast<double>(m) * azimuths_[k]);
      sin_[k * modes_ + m] = std::sin(static_cast<double>(m) * azimuths_[k]);
    }
  }
  m_.resize(modes_);
  m2_.resize(modes_);
  for (std::size_t m = 0; m < modes_; ++m) {
    m_[m] = static_cast<double>(m);
    m2_[m] = m_[m] * m_[m];
  }
}

Eigen::MatrixXd LogLinearAzimuthSeries::coefficients(const Eigen::MatrixXd& values) const {
  const Eigen::Index functions = values.rows();
  const std::size_t samples = static_cast<std::size_t>(values.cols()), modes = modes_;
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(functions, static_cast<Eigen::Index>(modes));
  if (modes == 0) return result;
  std::vector<double> integral(modes), f(samples), logs(samples);
  for (Eigen::Index row = 0; row < functions; ++row) {
    for (std::size_t k = 0; k < samples; ++k) f[k] = values(row, static_cast<Eigen::Index>(k));
    const double peak = *std::max_element(f.begin(), f.end());
    if (peak <= 0.0) continue;  // no light: all modes 0
    std::fill(integral.begin(), integral.end(), 0.0);
    for (std::size_t k = 0; k < samples; ++k) logs[k] = f[k] > 0.0 ? std::log(f[k]) : 0.0;
    for (std::size_t k = 0; k + 1 < samples; ++k) {
      const double fa = f[k], fb = f[k + 1];
      if (std::max(fa, fb) <= kNegligible * peak) continue;
      const double width = azimuths_[k + 1] - azimuths_[k];
      const double* ca = &cos_[k * modes];
      const double* cb = &cos_[(k + 1) * modes];
      const double* sa = &sin_[k * modes];
      const double* sb = &sin_[(k + 1) * modes];
      const double log_ratio = logs[k + 1] - logs[k];
      if (fa > 0.0 && fb > 0.0 && std::abs(log_ratio) >= kFlat) {  // exponential
        const double lambda = log_ratio / width, lambda2 = lambda * lambda;
        integral[0] += (fb - fa) / lambda;
        for (std::size_t m = 1; m < modes; ++m) {
          integral[m] += (lambda * (fb * cb[m] - fa * ca[m]) + m_[m] * (fb * sb[m] - fa * sa[m])) / (lambda2 + m2_[m]);
        }
      } else if (fa > 0.0 && fb > 0.0) {  // flat: f_a on the whole segment
        integral[0] += fa * width;
        for (std::size_t m = 1; m < modes; ++m) integral[m] += fa * (sb[m] - sa[m]) / m_[m];
      } else {  // linear toward or from a zero
        const double slope = (fb - fa) / width;
        integral[0] += 0.5 * (fa + fb) * width;
        for (std::size_t m = 1; m < modes; ++m) {
          integral[m] += fa * (sb[m] - sa[m]) / m_[m] + slope * (width * sb[m] / m_[m] + (cb[m] - ca[m]) / m2_[m]);
        }
      }
    }
    result(row, 0) = integral[0] / kPi;
    for (std::size_t m = 1; m < modes; ++m) result(row, static_cast<Eigen::Index>(m)) = 2.0 / kPi * integral[m];
  }
  return result;
}

LogLinearAzimuthSeries::Position LogLinearAzimuthSeries::locate(double phi) const {
  double folded = std::fmod(std::abs(phi), 2.0 * kPi);
  if (folded > kPi) folded = 2.0 * kPi - folded;
  const auto upper = std::upper_bound(azimuths_.begin(), azimuths_.end(), folded);
  if (upper == azimuths_.begin()) return {0, 0.0};
  if (upper == azimuths_.end()) return {azimuths_.size() - 1, 0.0};
  const auto k = static_cast<std::size_t>(upper - azimuths_.begin()) - 1;
  return {k, (folded - azimuths_[k]) / (azimuths_[k + 1] - azimuths_[k])};
}

double LogLinearAzimuthSeries::value(const double* values, const Position& at) const {
  const double fa = values[at.first];
  if (at.t == 0.0) return fa;
  const double fb = values[at.first + 1];
  if (fa > 0.0 && fb > 0.0) return fa * std::pow(fb / fa, at.t);
  return (1.0 - at.t) * fa + at.t * fb;
}

double LogLinearAzimuthSeries::value(std::span<const double> values, double phi) const {
  return value(values.data(), locate(phi));
}

}  // namespace skinlayer
