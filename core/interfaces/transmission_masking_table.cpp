#include "core/interfaces/transmission_masking_table.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/interfaces/microfacet_model.h"
#include "core/interfaces/smith_masking.h"
#include "core/series/catmull_rom.h"

namespace skinlayer {
namespace {

constexpr int kNodes = TransmissionMaskingRow::kNodes;
constexpr int kPadded = kNodes + 2;

// B(1/g_i, 1/g_o) at g = u^2 on the grid, with a ghost row and column beyond each end by cubic extrapolation
// (v_-1 = 3 v_0 - 3 v_1 + v_2), so that the Catmull-Rom stencil of the end cells needs no special case.
class BetaTable {
 public:
  BetaTable() : values_(kPadded * kPadded) {
    const auto g = [](int node) {
      const double u = static_cast<double>(node) / (kNodes - 1);
      return u * u;
    };
    for (int i = 0; i < kNodes; ++i)
      for (int j = 0; j < kNodes; ++j) at(i + 1, j + 1) = smith_g2_transmission(g(i), g(j), MicrofacetModel::Multiple);
    for (int j = 1; j <= kNodes; ++j) {
      at(0, j) = 3.0 * at(1, j) - 3.0 * at(2, j) + at(3, j);
      at(kNodes + 1, j) = 3.0 * at(kNodes, j) - 3.0 * at(kNodes - 1, j) + at(kNodes - 2, j);
    }
    for (int i = 0; i < kPadded; ++i) {
      at(i, 0) = 3.0 * at(i, 1) - 3.0 * at(i, 2) + at(i, 3);
      at(i, kNodes + 1) = 3.0 * at(i, kNodes) - 3.0 * at(i, kNodes - 1) + at(i, kNodes - 2);
    }
  }
  double at(int i, int j) const { return values_[static_cast<std::size_t>(i) * kPadded + j]; }

 private:
  double& at(int i, int j) { return values_[static_cast<std::size_t>(i) * kPadded + j]; }
  std::vector<double> values_;
};

// Built on first use and constant after: a cache of a pure function (~0.4 ms, once per process).
const BetaTable& beta_table() {
  static const BetaTable table;
  return table;
}

// The cell of grid coordinate x in [0, kNodes - 1] and the position t in it.
std::pair<int, double> cell_of(double u) {
  const double x = std::clamp(u, 0.0, 1.0) * (kNodes - 1);
  const int cell = std::min(static_cast<int>(x), kNodes - 2);
  return {cell, x - cell};
}

}  // namespace

TransmissionMaskingRow::TransmissionMaskingRow(double g1_in) {
  if (g1_in <= 0.0) {
    zero_ = true;
    return;
  }
  const BetaTable& table = beta_table();
  const auto [cell, t] = cell_of(std::sqrt(g1_in));
  double w[4];
  catmull_rom_weights(t, w);
  for (int j = 0; j < kPadded; ++j) {
    double sum = 0.0;
    for (int a = 0; a < 4; ++a) sum += w[a] * table.at(cell + a, j);  // padded rows cell .. cell + 3
    values_[j] = sum;
  }
}

}  // namespace skinlayer
