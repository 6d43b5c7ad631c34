#include "core/interfaces/multiple_scattering_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/conventions.h"
#include "core/data/embedded_table.h"
#include "core/series/catmull_rom.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

// The columns: sigma, E, kernel, theta_i, theta_o (degrees), the row's unit, then the values at the azimuths of the
// header ("p<degrees>"), in units.
constexpr int kKernelColumn = 2, kThetaIColumn = 3, kThetaOColumn = 4, kUnitColumn = 5, kFirstValueColumn = 6;
// Losses below this are none (their logarithms are interpolated).
constexpr double kLeastLoss = 1e-15;

// The table's grids, read once: sigma and E from the index columns (rows run over sigma, then E, then the kernels
// and angles, so that one (sigma, E) is a run of rows), the azimuths from the header.
struct Grid {
  std::vector<double> sigmas, indices, azimuths;
  std::vector<std::pair<int, int>> blocks;  // [sigma * indices + index]: its rows [first, last)
};

// The loss table's columns: sigma, E, side (0 from above, 1 from below), then l at the grid angles; rows in the
// lobe table's order of sigma and E, above before below.
constexpr int kLossFirstColumn = 3;

Grid read_grid(const data::EmbeddedTable& table) {
  Grid grid;
  std::size_t at = 0;
  for (int column = 0; column < table.columns; ++column) {
    const std::size_t next = table.header.find(',', at);
    const std::string_view name = table.header.substr(at, next == std::string_view::npos ? next : next - at);
    if (column >= kFirstValueColumn)
      grid.azimuths.push_back(degrees_to_radians(std::stod(std::string(name.substr(1)))));
    at = next + 1;
  }
  for (int r = 0; r < table.rows(); ++r) {
    const double sigma = table.at(r, 0), index = table.at(r, 1);
    if (grid.sigmas.empty() || sigma != grid.sigmas.back()) grid.sigmas.push_back(sigma);
    if (grid.sigmas.size() == 1 && (grid.indices.empty() || index != grid.indices.back())) {
      grid.indices.push_back(index);
    }
  }
  grid.blocks.assign(grid.sigmas.size() * grid.indices.size(), {0, 0});
  int first = 0;
  for (int r = 1; r <= table.rows(); ++r) {
    if (r < table.rows() && table.at(r, 0) == table.at(first, 0) && table.at(r, 1) == table.at(first, 1)) continue;
    const auto s = std::find(grid.sigmas.begin(), grid.sigmas.end(), table.at(first, 0)) - grid.sigmas.begin();
    const auto e = std::find(grid.indices.begin(), grid.indices.end(), table.at(first, 1)) - grid.indices.begin();
    if (static_cast<std::size_t>(e) >= grid.indices.size()) {
      throw std::logic_error("microfacet_multiple_scattering: the table's index grid differs between sigmas");
    }
    grid.blocks[static_cast<std::size_t>(s) * grid.indices.size() + static_cast<std::size_t>(e)] = {first, r};
    first = r;
  }
  for (const auto& [begin, end] : grid.blocks) {
    if (begin == end) throw std::logic_error("microfacet_multiple_scattering: the table is not a full sigma x E grid");
  }
  return grid;
}

// Four-point Lagrange weights of x on an ascending grid: the nodes, two on each side of x where the grid has them
// (fewer at its ends, down to two), and their weights; x clamped to the grid.
std::vector<std::pair<std::size_t, double>> cubic_weights(const std::vector<double>& nodes, double x) {
  if (nodes.size() == 1) return {{0, 1.0}};
  const double at = std::clamp(x, nodes.front(), nodes.back());
  const auto upper = static_cast<std::size_t>(std::upper_bound(nodes.begin(), nodes.end() - 1, at) - nodes.begin());
  const std::size_t lower = std::max<std::size_t>(upper, 1) - 1;  // the cell [lower, lower + 1] holding x
  const std::size_t first = lower == 0 ? 0 : lower - 1;
  const std::size_t last = std::min(nodes.size() - 1, lower + 2);
  std::vector<std::pair<std::size_t, double>> weights;
  for (std::size_t a = first; a <= last; ++a) {
    double w = 1.0;
    for (std::size_t b = first; b <= last; ++b) {
      if (b != a) w *= (at - nodes[b]) / (nodes[a] - nodes[b]);
    }
    weights.emplace_back(a, w);
  }
  return weights;
}

}  // namespace

PolarStencil polar_grid_stencil(double cosine) {
  constexpr int n = MultipleScatteringSamples::kAngles;
  const double x =
      std::acos(std::clamp(std::abs(cosine), 0.0, 1.0)) / degrees_to_radians(MultipleScatteringSamples::kAngleStep);
  const int cell = std::min(static_cast<int>(x), n - 2);
  PolarStencil stencil{};
  catmull_rom_weights(x - static_cast<double>(cell), stencil.weight.data());
  for (int p = 0; p < 4; ++p) stencil.index[static_cast<std::size_t>(p)] = std::clamp(cell + p - 1, 0, n - 1);
  return stencil;
}

std::array<double, MultipleScatteringSamples::kAngles> polar_grid_weights(double cosine) {
  const PolarStencil stencil = polar_grid_stencil(cosine);
  std::array<double, MultipleScatteringSamples::kAngles> weights{};
  for (std::size_t p = 0; p < 4; ++p) weights[static_cast<std::size_t>(stencil.index[p])] += stencil.weight[p];
  return weights;
}

const std::array<double, MultipleScatteringSamples::kAngles>& polar_grid_quadrature() {
  static const std::array<double, MultipleScatteringSamples::kAngles> quadrature = [] {
    std::array<double, MultipleScatteringSamples::kAngles> q{};
    const double step = degrees_to_radians(MultipleScatteringSamples::kAngleStep);
    const QuadratureRule rule = gauss_legendre(8, 0.0, 1.0);
    for (int cell = 0; cell + 1 < MultipleScatteringSamples::kAngles; ++cell) {
      for (int k = 0; k < rule.size(); ++k) {
        const double theta = (cell + rule.nodes[static_cast<std::size_t>(k)]) * step;
        const double measure =
            2.0 * kPi * std::cos(theta) * std::sin(theta) * step * rule.weights[static_cast<std::size_t>(k)];
        const auto w = polar_grid_weights(std::cos(theta));
        for (std::size_t a = 0; a < q.size(); ++a) q[a] += measure * w[a];
      }
    }
    return q;
  }();
  return quadrature;
}

MultipleScatteringShape multiple_scattering_shape(double sigma, double index) {
  const data::EmbeddedTable table = data::microfacet_multiple_scattering();
  const data::EmbeddedTable losses = data::microfacet_single_scattering_loss();
  static const Grid grid = read_grid(table);  // the compiled-in tables' grids: read once, never changed
  if (losses.rows() != static_cast<int>(2 * grid.blocks.size()) ||
      losses.columns != kLossFirstColumn + MultipleScatteringSamples::kAngles) {
    throw std::logic_error("microfacet_single_scattering_loss: not the lobe table's sigma x E grid");
  }
  constexpr auto n = static_cast<std::size_t>(MultipleScatteringSamples::kAngles);
  MultipleScatteringShape result;
  MultipleScatteringSamples& shapes = result.shapes;
  shapes.azimuths = grid.azimuths;
  const auto azimuths = static_cast<Eigen::Index>(grid.azimuths.size());
  // Summed row by row, as the table holds them (a row-major sum reads and writes each row in one stretch).
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  std::array<RowMajor, 3> sums;
  for (RowMajor& kernel : sums) kernel = RowMajor::Zero(n * n, azimuths);
  std::array<double, n> log_above{}, log_below{};

  std::vector<double> log_sigmas, sines;  // sines ascending: E descending
  for (const double s : grid.sigmas) log_sigmas.push_back(std::log(s));
  for (auto e = grid.indices.rbegin(); e != grid.indices.rend(); ++e) sines.push_back(1.0 / *e);
  const auto sigma_weights = cubic_weights(log_sigmas, std::log(sigma));
  const auto sine_weights = cubic_weights(sines, 1.0 / std::max(index, 1.0));
  for (const auto& [s, sigma_weight] : sigma_weights) {
    for (const auto& [sine, sine_weight] : sine_weights) {
      const double weight = sigma_weight * sine_weight;
      const std::size_t block = s * grid.indices.size() + (grid.indices.size() - 1 - sine);
      for (std::size_t k = 0; k < n; ++k) {
        const int column = kLossFirstColumn + static_cast<int>(k);
        log_above[k] += weight * std::log(std::max(losses.at(static_cast<int>(2 * block), column), kLeastLoss));
        log_below[k] += weight * std::log(std::max(losses.at(static_cast<int>(2 * block + 1), column), kLeastLoss));
      }
      const auto [first, last] = grid.blocks[block];
      for (int r = first; r < last; ++r) {
        const auto kernel = static_cast<std::size_t>(table.at(r, kKernelColumn));
        const auto i =
            static_cast<std::size_t>(std::lround(table.at(r, kThetaIColumn) / MultipleScatteringSamples::kAngleStep));
        const auto o =
            static_cast<std::size_t>(std::lround(table.at(r, kThetaOColumn) / MultipleScatteringSamples::kAngleStep));
        const double unit = weight * table.at(r, kUnitColumn);
        const Eigen::Map<const Eigen::RowVectorXd> values(&table.values[static_cast<std::size_t>(r) * table.columns +
                                                                        kFirstValueColumn],
                                                          azimuths);
        sums[kernel].row(static_cast<Eigen::Index>(i * n + o)) += unit * values;
      }
    }
  }
  for (std::size_t kernel = 0; kernel < 3; ++kernel) {
    // The mirror halves of the reciprocal reflections, which the table leaves out: of each pair (i, o), (o, i) one
    // row holds the sum and the other none.
    for (std::size_t i = 0; kernel < 2 && i < n; ++i) {
      for (std::size_t o = 0; o < i; ++o) {
        const auto a = static_cast<Eigen::Index>(i * n + o), b = static_cast<Eigen::Index>(o * n + i);
        sums[kernel].row(a) += sums[kernel].row(b);
        sums[kernel].row(b) = sums[kernel].row(a);
      }
    }
    // The cubic weights may overshoot below zero beside a steep change between grid nodes; a BSDF may not.
    shapes.kernels[kernel] = sums[kernel].cwiseMax(0.0);
  }
  for (std::size_t k = 0; k < n; ++k) {
    result.loss_above[k] = log_above[k] <= std::log(kLeastLoss) ? 0.0 : std::exp(log_above[k]);
    result.loss_below[k] = log_below[k] <= std::log(kLeastLoss) ? 0.0 : std::exp(log_below[k]);
  }
  return result;
}

}  // namespace skinlayer
