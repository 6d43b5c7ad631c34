#include "core/series/weighted_tables.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace skinlayer {

namespace {

// Adds w times a's coefficients (modes_a modes of K x K) into sum (modes_sum >= modes_a modes of K x K).
void add_scaled(std::span<const double> a, double w, std::vector<double>& sum) {
  for (std::size_t i = 0; i < a.size(); ++i) sum[i] += w * a[i];  // mode m starts at m K^2 in both
}

}  // namespace

LayerTables weighted_sum(std::span<const LayerTables> tables, std::span<const double> weights) {
  if (tables.empty() || tables.size() != weights.size()) {
    throw std::invalid_argument("weighted_sum: " + std::to_string(tables.size()) + " tables and " +
                                std::to_string(weights.size()) + " weights (need as many, at least one)");
  }
  const int k = tables.front().grid_size();
  int modes = 0;
  for (const LayerTables& t : tables) {
    if (t.grid_size() != k) {
      throw std::invalid_argument("weighted_sum: grid sizes " + std::to_string(k) + " and " +
                                  std::to_string(t.grid_size()) + " differ");
    }
    if (!(t.unscattered().scaled(1.0) == tables.front().unscattered().scaled(1.0))) {
      throw std::invalid_argument("weighted_sum: the tables carry different unscattered light, which does not tabulate");
    }
    modes = std::max(modes, t.modes());
  }
  double unscattered_weight = 0.0;
  for (std::size_t i = 0; i < tables.size(); ++i) unscattered_weight += weights[i] * tables[i].unscattered().weight();
  const std::size_t size = static_cast<std::size_t>(modes) * static_cast<std::size_t>(k) * static_cast<std::size_t>(k);
  std::vector<double> reflection(size, 0.0), transmission(size, 0.0);
  for (std::size_t i = 0; i < tables.size(); ++i) {
    add_scaled(tables[i].reflection_coefficients(), weights[i], reflection);
    add_scaled(tables[i].transmission_coefficients(), weights[i], transmission);
  }
  return LayerTables(k, modes, std::move(reflection), std::move(transmission),
                     tables.front().unscattered().scaled(unscattered_weight));
}

}  // namespace skinlayer
