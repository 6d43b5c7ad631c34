#include "core/unscattered/bottom_bounce.h"

#include <algorithm>
#include <cmath>

namespace skinlayer {

Eigen::MatrixXd bottom_bounce_image(const InterfaceKernels& kernels, const Eigen::VectorXd& attenuation, int m) {
  const auto mode = static_cast<std::size_t>(m);
  return kernels.t_exit.kernel[mode] * (attenuation.asDiagonal() * kernels.r_bottom[mode] *
                                        (attenuation.asDiagonal() * kernels.t_source.kernel[mode]));
}

bool bottom_bounce_matters(const Eigen::MatrixXd& image_mode0, std::span<const Eigen::MatrixXd> reflection_mode0,
                           double fraction) {
  for (const Eigen::MatrixXd& table : reflection_mode0) {
    const double counted = 1e-3 * table.maxCoeff();
    for (Eigen::Index i = 0; i < table.cols(); ++i) {
      for (Eigen::Index o = 0; o < table.rows(); ++o) {
        if (table(o, i) > counted && std::abs(image_mode0(o, i)) >= fraction * table(o, i)) return true;
      }
    }
  }
  return false;
}

int bottom_bounce_ordinates(int ordinates, const RoughDielectric& top) {
  const double lobe = std::ceil(1.75 / refracted_lobe_width(top));  // the N rule's need for the refracted lobe
  const int finer = static_cast<int>(std::clamp(4.0 * lobe, 96.0, 256.0));
  return std::max(ordinates, (finer + 3) / 4 * 4);
}

}  // namespace skinlayer
