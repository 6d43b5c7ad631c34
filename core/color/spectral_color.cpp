#include "core/color/spectral_color.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/data/embedded_table.h"

namespace skinlayer {
namespace {

// cmf(lambda) D65(lambda) at each row of the CMF table (1 nm, 360-830 nm; D65 covers 300-830 nm).
struct WeightedObserver {
  data::EmbeddedTable cmf = data::cie1931_2deg_cmf();
  data::EmbeddedTable d65 = data::cie_d65();
  Eigen::Vector3d at(int row) const {
    const double power = d65.interpolate(1, cmf.at(row, 0));
    return Eigen::Vector3d(cmf.at(row, 1), cmf.at(row, 2), cmf.at(row, 3)) * power;
  }
  double white_y() const {
    double sum = 0.0;
    for (int row = 0; row < cmf.rows(); ++row) sum += at(row).y();
    return sum;
  }
};

// The hat function b_k of the grid at lambda: linear between nodes, 1 beyond the end node k.
double hat(std::span<const double> grid, std::size_t k, double lambda) {
  const std::size_t n = grid.size();
  if (n == 1) return 1.0;
  if (k == 0 && lambda <= grid[0]) return 1.0;
  if (k == n - 1 && lambda >= grid[n - 1]) return 1.0;
  if (k > 0 && lambda > grid[k - 1] && lambda <= grid[k]) return (lambda - grid[k - 1]) / (grid[k] - grid[k - 1]);
  if (k + 1 < n && lambda >= grid[k] && lambda < grid[k + 1]) return (grid[k + 1] - lambda) / (grid[k + 1] - grid[k]);
  return 0.0;
}

}  // namespace

Eigen::Vector3d d65_white_xyz() {
  const WeightedObserver observer;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int row = 0; row < observer.cmf.rows(); ++row) sum += observer.at(row);
  return sum / sum.y();
}

Eigen::Matrix3d xyz_to_linear_srgb() {
  const double primaries[3][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
  Eigen::Matrix3d columns;  // XYZ of each primary at Y = 1
  for (int c = 0; c < 3; ++c) {
    const double x = primaries[c][0], y = primaries[c][1];
    columns.col(c) = Eigen::Vector3d(x / y, 1.0, (1.0 - x - y) / y);
  }
  const Eigen::Vector3d scale = columns.inverse() * d65_white_xyz();  // primaries' strengths that sum to white
  return (columns * scale.asDiagonal()).inverse();
}

Eigen::Matrix<double, 3, Eigen::Dynamic> linear_srgb_weights(std::span<const double> wavelengths) {
  if (wavelengths.empty()) throw std::invalid_argument("linear_srgb_weights: no wavelengths");
  if (!std::is_sorted(wavelengths.begin(), wavelengths.end()) ||
      std::adjacent_find(wavelengths.begin(), wavelengths.end()) != wavelengths.end()) {
    throw std::invalid_argument("linear_srgb_weights: the wavelengths must ascend");
  }
  const WeightedObserver observer;
  const double white_y = observer.white_y();
  const auto n = static_cast<Eigen::Index>(wavelengths.size());
  Eigen::Matrix<double, 3, Eigen::Dynamic> xyz = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, n);
  for (int row = 0; row < observer.cmf.rows(); ++row) {
    const double lambda = observer.cmf.at(row, 0);
    const Eigen::Vector3d value = observer.at(row) / white_y;
    for (Eigen::Index k = 0; k < n; ++k) {
      const double b = hat(wavelengths, static_cast<std::size_t>(k), lambda);
      if (b != 0.0) xyz.col(k) += b * value;
    }
  }
  return xyz_to_linear_srgb() * xyz;
}

double srgb_encode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

}  // namespace skinlayer
