#include "core/interfaces/multiple_scattering.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"
#include "core/data/embedded_table.h"

namespace skinlayer {
namespace {

constexpr int kFirstBinColumn = 3;  // sigma, index, mu_i, then r0.., t0.. (as many exit bins as incident angles)

// The table's grids, read from its first columns: sigma (outer), index, incident cosine (inner).
struct Grid {
  std::vector<double> sigmas, indices, mus;
};

Grid read_grid(const data::EmbeddedTable& table) {
  Grid grid;
  for (int r = 0; r < table.rows(); ++r) {
    const double sigma = table.at(r, 0), index = table.at(r, 1), mu = table.at(r, 2);
    if (grid.sigmas.empty() || sigma != grid.sigmas.back()) grid.sigmas.push_back(sigma);
    if (grid.sigmas.size() == 1 && (grid.indices.empty() || index != grid.indices.back())) {
      grid.indices.push_back(index);
    }
    if (grid.sigmas.size() == 1 && grid.indices.size() == 1) grid.mus.push_back(mu);
  }
  if (static_cast<std::size_t>(table.rows()) != grid.sigmas.size() * grid.indices.size() * grid.mus.size() ||
      table.columns != kFirstBinColumn + 2 * static_cast<int>(grid.mus.size())) {
    throw std::logic_error("microfacet_multiple_scattering: the table is not a full sigma x index x mu grid");
  }
  return grid;
}

// Linear interpolation weights of x on an ascending grid (clamped at its ends): the lower node and the weight of
// the upper one.
std::pair<std::size_t, double> bracket(const std::vector<double>& nodes, double x) {
  if (x <= nodes.front()) return {0, 0.0};
  if (x >= nodes.back()) return {nodes.size() - 2, 1.0};
  const std::size_t upper = static_cast<std::size_t>(std::upper_bound(nodes.begin(), nodes.end(), x) - nodes.begin());
  return {upper - 1, (x - nodes[upper - 1]) / (nodes[upper] - nodes[upper - 1])};
}

}  // namespace

MultipleScatteringLobe::MultipleScatteringLobe(const RoughDielectric& interface) : eta_(interface.eta) {
  const data::EmbeddedTable table = data::microfacet_multiple_scattering();
  static const Grid grid = read_grid(table);  // the compiled-in table's grid: read once, never changed
  const std::size_t bins = grid.mus.size();
  for (const double mu : grid.mus) angles_.push_back(std::acos(mu));
  std::vector<double> log_indices;
  for (const double index : grid.indices) log_indices.push_back(std::log(index));
  const auto [s0, ws] = bracket(grid.sigmas, interface.sigma);
  for (int from = 0; from < 2; ++from) {
    Side& side = sides_[static_cast<std::size_t>(from)];
    side.reflection.assign(bins, std::vector<double>(bins, 0.0));
    side.transmission.assign(bins, std::vector<double>(bins, 0.0));
    if (interface.eta == 1.0) continue;
    const double index = from == 0 ? interface.eta : 1.0 / interface.eta;
    const auto [e0, we] = bracket(log_indices, std::log(index));
    for (std::size_t m = 0; m < bins; ++m) {
      for (int corner = 0; corner < 4; ++corner) {
        const std::size_t s = s0 + (corner & 1), e = e0 + (corner >> 1);
        const double weight = ((corner & 1) ? ws : 1.0 - ws) * ((corner >> 1) ? we : 1.0 - we);
        if (weight == 0.0) continue;
        const int row = static_cast<int>((s * grid.indices.size() + e) * bins + m);
        for (std::size_t b = 0; b < bins; ++b) {
          side.reflection[m][b] += weight * table.at(row, kFirstBinColumn + static_cast<int>(b));
          side.transmission[m][b] += weight * table.at(row, kFirstBinColumn + static_cast<int>(bins + b));
        }
      }
    }
  }
  // The shares, from the table's reciprocal lobes on its own grid (the exit bins are centred on the incident
  // angles, so the swapped pair is a table entry too): over a bin theta in [a, b], int f mu_o d omega_o =
  // pi (sin^2 b - sin^2 a) f.
  const std::size_t n = angles_.size();
  std::vector<double> bin_weight(n);
  for (std::size_t b = 0; b < n; ++b) {
    const double half = b + 1 < n ? 0.5 * (angles_[b + 1] - angles_[b]) : 0.5 * (angles_[b] - angles_[b - 1]);
    const double lo = std::max(0.0, angles_[b] - half), hi = std::min(0.5 * kPi, angles_[b] + half);
    bin_weight[b] = kPi * (std::sin(hi) * std::sin(hi) - std::sin(lo) * std::sin(lo));
  }
  const Side& above = sides_[0];
  const Side& below = sides_[1];
  for (std::size_t from = 0; from < 2; ++from) {
    const Side& side = sides_[from];
    std::vector<double> shares;
    for (std::size_t i = 0; i < n; ++i) {
      double reflected = 0.0, transmitted = 0.0;
      for (std::size_t o = 0; o < n; ++o) {
        reflected += bin_weight[o] * 0.5 * (side.reflection[i][o] + side.reflection[o][i]);
        // above i -> below o, or below i -> above o (the reciprocal of above o -> below i, / eta^2).
        const double t = from == 0 ? 0.5 * (above.transmission[i][o] + eta_ * eta_ * below.transmission[o][i])
                                   : 0.5 * (above.transmission[o][i] / (eta_ * eta_) + below.transmission[i][o]);
        transmitted += bin_weight[o] * t;
      }
      shares.push_back(reflected + transmitted > 0.0 ? transmitted / (reflected + transmitted) : 0.5);
    }
    sides_[from].share = std::move(shares);
  }
}

std::pair<std::size_t, double> MultipleScatteringLobe::node(double mu) const {
  return bracket(angles_, std::acos(std::clamp(mu, 0.0, 1.0)));
}

double MultipleScatteringLobe::raw(const Side& side, bool reflect, double mu_i, double mu_o) const {
  // Catmull-Rom in both angles (the grid is uniform in angle), the end nodes repeated beyond the grid; a cubic can
  // overshoot below zero beside a steep rise, so the result is held at 0 or above.
  const auto [i, ti] = node(mu_i);
  const auto [o, to] = node(mu_o);
  const std::vector<std::vector<double>>& f = reflect ? side.reflection : side.transmission;
  const auto n = static_cast<std::ptrdiff_t>(f.size());
  const auto clamp_index = [n](std::ptrdiff_t k) {
    return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(k, 0, n - 1));
  };
  const auto weights = [](double t) {
    return std::array<double, 4>{0.5 * (-t + 2.0 * t * t - t * t * t), 0.5 * (2.0 - 5.0 * t * t + 3.0 * t * t * t),
                                 0.5 * (t + 4.0 * t * t - 3.0 * t * t * t), 0.5 * (-t * t + t * t * t)};
  };
  const std::array<double, 4> wi = weights(ti), wo = weights(to);
  double sum = 0.0;
  for (int a = 0; a < 4; ++a) {
    const std::vector<double>& row = f[clamp_index(static_cast<std::ptrdiff_t>(i) + a - 1)];
    double inner = 0.0;
    for (int b = 0; b < 4; ++b)
      inner += wo[static_cast<std::size_t>(b)] * row[clamp_index(static_cast<std::ptrdiff_t>(o) + b - 1)];
    sum += wi[static_cast<std::size_t>(a)] * inner;
  }
  return std::max(sum, 0.0);
}

double MultipleScatteringLobe::raw_reflection(bool from_above, double mu_i, double mu_o) const {
  return raw(sides_[from_above ? 0 : 1], true, mu_i, mu_o);
}

double MultipleScatteringLobe::raw_transmission(bool from_above, double mu_i, double mu_o) const {
  return raw(sides_[from_above ? 0 : 1], false, mu_i, mu_o);
}

double MultipleScatteringLobe::reflection(bool from_above, double mu_i, double mu_o) const {
  return 0.5 * (raw_reflection(from_above, mu_i, mu_o) + raw_reflection(from_above, mu_o, mu_i));
}

double MultipleScatteringLobe::transmission(bool from_above, double mu_i, double mu_o) const {
  if (!from_above) return transmission(true, mu_o, mu_i) / (eta_ * eta_);
  return 0.5 * (raw_transmission(true, mu_i, mu_o) + eta_ * eta_ * raw_transmission(false, mu_o, mu_i));
}

double MultipleScatteringLobe::transmitted_share(bool from_above, double mu_i) const {
  const Side& side = sides_[from_above ? 0 : 1];
  const auto [i, w] = node(mu_i);
  return (1.0 - w) * side.share[i] + w * side.share[i + 1];
}

}  // namespace skinlayer
