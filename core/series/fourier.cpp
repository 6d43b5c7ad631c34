#include "core/series/fourier.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"

namespace skinlayer {

CosineProjector::CosineProjector(int modes, int samples) : weights_(modes, samples), cos_(samples), sin_(samples) {
  if (modes < 1 || samples < 2) throw std::invalid_argument("CosineProjector: need modes >= 1 and samples >= 2");
  const double step = kPi / (samples - 1);
  for (int k = 0; k < samples; ++k) {
    const double trapezoid = (k == 0 || k == samples - 1) ? 0.5 * step : step;
    const double phi = k * step;
    cos_[k] = std::cos(phi);
    sin_[k] = std::sin(phi);
    for (int m = 0; m < modes; ++m) {
      const double scale = (m == 0 ? 1.0 : 2.0) / kPi;
      weights_(m, k) = scale * trapezoid * std::cos(m * phi);
    }
  }
}

double CosineProjector::angle(int k) const { return k * kPi / (samples() - 1); }

Eigen::MatrixXd CosineProjector::project(const Eigen::MatrixXd& samples, const CancelCheck& cancelled) const {
  Eigen::MatrixXd coefficients(weights_.rows(), samples.cols());
  for (Eigen::Index start = 0; start < samples.cols(); start += kProjectBlock) {
    throw_if_cancelled(cancelled);
    const Eigen::Index width = std::min(kProjectBlock, samples.cols() - start);
    coefficients.middleCols(start, width).noalias() = weights_ * samples.middleCols(start, width);
  }
  return coefficients;
}

AdaptiveCosineSeries::AdaptiveCosineSeries(int max_modes, double tolerance) : tolerance_(tolerance) {
  if (max_modes < 16) throw std::invalid_argument("AdaptiveCosineSeries: need max_modes >= 16");
  for (int modes = 16; modes <= max_modes; modes *= 2) projectors_.emplace_back(modes, 2 * modes + 1);
}

std::vector<double> AdaptiveCosineSeries::operator()(const std::function<double(double phi)>& function) const {
  Eigen::VectorXd samples;
  for (std::size_t level = 0; level < projectors_.size(); ++level) {
    const CosineProjector& projector = projectors_[level];
    Eigen::VectorXd next(projector.samples());
    for (int k = 0; k < projector.samples(); ++k) {
      next(k) = (level > 0 && k % 2 == 0) ? samples(k / 2) : function(projector.angle(k));
    }
    samples = std::move(next);
    const Eigen::VectorXd coefficients = projector.project(samples);
    const int modes = projector.modes();
    const double tail = coefficients.tail(modes / 2).cwiseAbs().sum();
    if (tail <= tolerance_ * samples.cwiseAbs().maxCoeff() || level + 1 == projectors_.size()) {
      return {coefficients.data(), coefficients.data() + modes};
    }
  }
  return {};
}

std::size_t matrix_bytes(const Eigen::MatrixXd& matrix) {
  return sizeof(double) * static_cast<std::size_t>(matrix.size());
}

std::size_t fourier_kernel_bytes(const FourierKernel& kernel) {
  std::size_t bytes = 0;
  for (const Eigen::MatrixXd& m : kernel) bytes += matrix_bytes(m);
  return bytes;
}

Vec3 propagation_direction(double mu, double phi) {
  const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
  return {s * std::cos(phi), s * std::sin(phi), mu};
}

}  // namespace skinlayer
