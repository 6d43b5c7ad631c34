#include "core/color/rgb_uplift.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/color/spectral_color.h"

namespace skinlayer {
namespace {

// S(z) = 1/2 + z / (2 sqrt(1 + z^2)) and its derivative S'(z) = 1 / (2 (1 + z^2)^(3/2)).
double sigmoid(double z) { return 0.5 + 0.5 * z / std::sqrt(1.0 + z * z); }
double sigmoid_slope(double z) { return 0.5 / std::pow(1.0 + z * z, 1.5); }
// S^-1(y) for y in (0, 1).
double inverse_sigmoid(double y) { return (y - 0.5) / std::sqrt(y * (1.0 - y)); }

constexpr int kMaxIterations = 200;
constexpr double kTolerance = 1e-10;  // on |W R - t|, whose largest target component is 1/2

}  // namespace

RgbUplift::RgbUplift(std::span<const double> wavelengths) : wavelengths_(wavelengths.begin(), wavelengths.end()) {
  if (wavelengths_.size() < 3) throw std::invalid_argument("RgbUplift: needs at least 3 wavelengths");
  weights_ = linear_srgb_weights(wavelengths_);  // checks that they ascend
  const double l0 = wavelengths_.front(), l1 = wavelengths_.back();
  for (const double lambda : wavelengths_) x_.push_back((lambda - l0) / (l1 - l0));
}

SigmoidSpectrum RgbUplift::fit(const std::array<double, 3>& rgb, const std::array<double, 3>* start) const {
  for (const double v : rgb) {
    if (!std::isfinite(v) || v < 0.0) throw std::invalid_argument("RgbUplift: rgb components must be finite and >= 0");
  }
  SigmoidSpectrum spectrum;
  const double largest = std::max({rgb[0], rgb[1], rgb[2]});
  if (largest == 0.0) return spectrum;
  spectrum.scale = 2.0 * largest;
  const Eigen::Vector3d target = Eigen::Vector3d(rgb[0], rgb[1], rgb[2]) / spectrum.scale;
  Eigen::Vector3d c = start ? Eigen::Vector3d((*start)[0], (*start)[1], (*start)[2])
                            : Eigen::Vector3d(0.0, 0.0, inverse_sigmoid(std::clamp(target.mean(), 1e-6, 0.5)));
  const Eigen::Index n = static_cast<Eigen::Index>(x_.size());
  const auto residual = [&](const Eigen::Vector3d& k) {
    Eigen::VectorXd r(n);
    for (Eigen::Index i = 0; i < n; ++i) r[i] = sigmoid((k[0] * x_[i] + k[1]) * x_[i] + k[2]);
    return Eigen::Vector3d(weights_ * r - target);
  };
  Eigen::Vector3d r = residual(c);
  double damping = 1e-3;
  for (int iteration = 0; iteration < kMaxIterations && r.cwiseAbs().maxCoeff() > kTolerance; ++iteration) {
    Eigen::Matrix<double, Eigen::Dynamic, 3> dr_dc(n, 3);  // dR_i / dc
    for (Eigen::Index i = 0; i < n; ++i) {
      const double x = x_[i], slope = sigmoid_slope((c[0] * x + c[1]) * x + c[2]);
      dr_dc.row(i) << slope * x * x, slope * x, slope;
    }
    const Eigen::Matrix3d jacobian = weights_ * dr_dc;
    const Eigen::Matrix3d normal = jacobian.transpose() * jacobian;
    const Eigen::Vector3d gradient = jacobian.transpose() * r;
    bool improved = false;
    while (!improved && damping < 1e12) {
      Eigen::Matrix3d damped = normal;
      damped.diagonal() *= 1.0 + damping;
      const Eigen::Vector3d trial = c - damped.partialPivLu().solve(gradient);
      const Eigen::Vector3d trial_r = residual(trial);
      if (trial.allFinite() && trial_r.squaredNorm() < r.squaredNorm()) {
        c = trial;
        r = trial_r;
        damping = std::max(damping * 0.1, 1e-9);
        improved = true;
      } else {
        damping *= 10.0;
      }
    }
    if (!improved) break;  // no step reduces the residual: the nearest reachable colour
  }
  spectrum.coefficients = {c[0], c[1], c[2]};
  spectrum.rgb_error = r.cwiseAbs().maxCoeff() / target.maxCoeff();
  return spectrum;
}

void RgbUplift::values(const SigmoidSpectrum& spectrum, std::span<double> out) const {
  if (out.size() != x_.size()) throw std::invalid_argument("RgbUplift::values: one value per wavelength");
  const auto& c = spectrum.coefficients;
  for (std::size_t i = 0; i < x_.size(); ++i) {
    out[i] = spectrum.scale == 0.0 ? 0.0 : spectrum.scale * sigmoid((c[0] * x_[i] + c[1]) * x_[i] + c[2]);
  }
}

std::array<double, 3> RgbUplift::rgb_of(std::span<const double> values) const {
  if (values.size() != x_.size()) throw std::invalid_argument("RgbUplift::rgb_of: one value per wavelength");
  const Eigen::Vector3d rgb =
      weights_ * Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  return {rgb[0], rgb[1], rgb[2]};
}

}  // namespace skinlayer
