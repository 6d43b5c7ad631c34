#include "core/interfaces/smith_masking.h"

#include <math.h>  // lgamma_r

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
  // lgamma_r, not std::lgamma: std::lgamma writes the sign to the global signgam, a data race when kernels are built
  // on several threads. Every argument here is >= 1, so the sign is always +.
  int sign = 0;
  return std::exp(::lgamma_r(a, &sign) + ::lgamma_r(b, &sign) - ::lgamma_r(a + b, &sign));
}

}  // namespace skinlayer
