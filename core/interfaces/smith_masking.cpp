#include "core/interfaces/smith_masking.h"

#include <cmath>

namespace skinlayer {

double smith_g2_reflection(double g1_i, double g1_o, MicrofacetModel model) {
  if (g1_i <= 0.0 || g1_o <= 0.0) return 0.0;
  if (model == MicrofacetModel::Single) return g1_i * g1_o;
  return 1.0 / (1.0 / g1_i + 1.0 / g1_o - 1.0);  // 1 + Lambda = 1 / G1
}

double smith_g2_transmission(double g1_i, double g1_o, MicrofacetModel model) {
  if (g1_i <= 0.0 || g1_o <= 0.0) return 0.0;
  if (model == MicrofacetModel::Single) return g1_i * g1_o;
  const double a = 1.0 / g1_i, b = 1.0 / g1_o;  // 1 + Lambda of each
  return std::exp(std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b));
}

}  // namespace skinlayer
