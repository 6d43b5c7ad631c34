#include "core/solve/adding.h"

#include <Eigen/LU>

namespace skinlayer {

LayerPair symmetric_layer(const LayerOperators& operators) { return {operators, operators}; }

LayerPair add_layers(const LayerPair& a, const LayerPair& b) {
  const Eigen::Index n = a.from_above.reflection.rows();
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
  // Light going down between the layers: (I - R*_a R_b)^-1; going up: (I - R_b R*_a)^-1.
  const Eigen::PartialPivLU<Eigen::MatrixXd> down(identity - a.from_below.reflection * b.from_above.reflection);
  const Eigen::PartialPivLU<Eigen::MatrixXd> up(identity - b.from_above.reflection * a.from_below.reflection);
  LayerPair result;
  result.from_above.reflection =
      a.from_above.reflection +
      a.from_below.transmission * up.solve(b.from_above.reflection * a.from_above.transmission);
  result.from_above.transmission = b.from_above.transmission * down.solve(a.from_above.transmission);
  result.from_below.reflection =
      b.from_below.reflection +
      b.from_above.transmission * down.solve(a.from_below.reflection * b.from_below.transmission);
  result.from_below.transmission = a.from_below.transmission * up.solve(b.from_below.transmission);
  return result;
}

Eigen::MatrixXd reflection_over(const LayerPair& a, const Eigen::MatrixXd& base) {
  const Eigen::Index n = base.rows();
  const Eigen::PartialPivLU<Eigen::MatrixXd> up(Eigen::MatrixXd::Identity(n, n) - base * a.from_below.reflection);
  return a.from_above.reflection + a.from_below.transmission * up.solve(base * a.from_above.transmission);
}

}  // namespace skinlayer
