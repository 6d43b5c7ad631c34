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
    : azimuths_(azimuths.begin(), azimuths.end()), modes_(std::max(modes, 0)) {
  const auto samples = static_cast<Eigen::Index>(azimuths_.size());
  m_ = Eigen::ArrayXd::LinSpaced(modes_, 0.0, static_cast<double>(modes_ - 1));
  m2_ = m_.square();
  cos_.resize(modes_, samples);
  sin_.resize(modes_, samples);
  for (Eigen::Index k = 0; k < samples; ++k) {
    cos_.col(k) = (m_ * azimuths_[static_cast<std::size_t>(k)]).cos().matrix();
    sin_.col(k) = (m_ * azimuths_[static_cast<std::size_t>(k)]).sin().matrix();
  }
}

Eigen::MatrixXd LogLinearAzimuthSeries::coefficients(const Eigen::MatrixXd& values) const {
  const Eigen::Index functions = values.rows(), samples = values.cols();
  Eigen::MatrixXd result = Eigen::MatrixXd::Zero(functions, modes_);
  if (modes_ == 0) return result;
  Eigen::ArrayXd integral(modes_);
  Eigen::ArrayXd logs(samples);
  for (Eigen::Index f = 0; f < functions; ++f) {
    const double peak = values.row(f).maxCoeff();
    if (peak <= 0.0) continue;  // no light: all modes 0
    integral.setZero();
    for (Eigen::Index k = 0; k < samples; ++k) logs(k) = values(f, k) > 0.0 ? std::log(values(f, k)) : 0.0;
    for (Eigen::Index k = 0; k + 1 < samples; ++k) {
      const double fa = values(f, k), fb = values(f, k + 1);
      if (std::max(fa, fb) <= kNegligible * peak) continue;
      const double a = azimuths_[static_cast<std::size_t>(k)], b = azimuths_[static_cast<std::size_t>(k + 1)];
      const double width = b - a;
      const auto ca = cos_.col(k).array(), cb = cos_.col(k + 1).array();
      const auto sa = sin_.col(k).array(), sb = sin_.col(k + 1).array();
      if (fa > 0.0 && fb > 0.0) {
        const double log_ratio = logs(k + 1) - logs(k);
        if (std::abs(log_ratio) < kFlat) {  // flat: f_a on the whole segment
          integral(0) += fa * width;
          integral.tail(modes_ - 1) += fa * (sb - sa).tail(modes_ - 1) / m_.tail(modes_ - 1);
          continue;
        }
        const double lambda = log_ratio / width;
        integral(0) += (fb - fa) / lambda;
        integral.tail(modes_ - 1) += (lambda * (fb * cb - fa * ca) + m_ * (fb * sb - fa * sa)).tail(modes_ - 1) /
                                     (lambda * lambda + m2_.tail(modes_ - 1));
        continue;
      }
      // Linear toward or from a zero.
      const double slope = (fb - fa) / width;
      integral(0) += 0.5 * (fa + fb) * width;
      const auto rest = Eigen::seqN(1, modes_ - 1);
      integral(rest) +=
          fa * (sb - sa)(rest) / m_(rest) + slope * (width * sb(rest) / m_(rest) + (cb - ca)(rest) / m2_(rest));
    }
    result(f, 0) = integral(0) / kPi;
    result.row(f).tail(modes_ - 1) = (2.0 / kPi) * integral.tail(modes_ - 1).matrix().transpose();
  }
  return result;
}

double LogLinearAzimuthSeries::value(std::span<const double> values, double phi) const {
  double folded = std::fmod(std::abs(phi), 2.0 * kPi);
  if (folded > kPi) folded = 2.0 * kPi - folded;
  const auto upper = std::upper_bound(azimuths_.begin(), azimuths_.end(), folded);
  if (upper == azimuths_.begin()) return values.front();
  if (upper == azimuths_.end()) return values.back();
  const auto k = static_cast<std::size_t>(upper - azimuths_.begin()) - 1;
  const double t = (folded - azimuths_[k]) / (azimuths_[k + 1] - azimuths_[k]);
  const double fa = values[k], fb = values[k + 1];
  if (fa > 0.0 && fb > 0.0) return fa * std::pow(fb / fa, t);
  return (1.0 - t) * fa + t * fb;
}

}  // namespace skinlayer
