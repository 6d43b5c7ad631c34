#include "core/interfaces/multiple_scattering.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"
#include "core/data/embedded_table.h"
#include "core/interfaces/interface_albedo.h"
#include "core/series/quadrature.h"

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
  const Grid grid = read_grid(table);
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
  // The shares, from the table's reciprocal lobes: over the exit hemisphere int f mu_o d omega_o = pi int_0^1 f du,
  // u = mu_o^2.
  const QuadratureRule u = gauss_legendre(96, 0.0, 1.0);
  for (int from = 0; from < 2; ++from) {
    Side& side = sides_[static_cast<std::size_t>(from)];
    for (const double mu : grid.mus) {
      double reflected = 0.0, transmitted = 0.0;
      for (int k = 0; k < u.size(); ++k) {
        const double mu_o = std::sqrt(u.nodes[k]);
        reflected += u.weights[k] * symmetric_reflection(from == 0, mu, mu_o);
        transmitted += u.weights[k] * (from == 0 ? symmetric_transmission(mu, mu_o)
                                                 : symmetric_transmission(mu_o, mu) / (eta_ * eta_));
      }
      side.share.push_back(reflected + transmitted > 0.0 ? transmitted / (reflected + transmitted) : 0.5);
    }
  }
  balance(interface);
}

void MultipleScatteringLobe::balance(const RoughDielectric& interface) {
  constexpr int kMaxSteps = 200;
  constexpr double kTolerance = 1e-9;
  const std::size_t n = angles_.size();
  for (Side& side : sides_) {
    side.reflection_scale.assign(n, 1.0);
    side.transmission_scale.assign(n, 1.0);
  }
  if (eta_ == 1.0) return;
  // The energies wanted at the grid's angles, from the exact single-scattering loss.
  std::array<std::vector<double>, 2> reflect_target, transmit_target;
  for (std::size_t from = 0; from < 2; ++from) {
    std::vector<Vec3> wi;
    for (const double angle : angles_) wi.emplace_back(std::sin(angle), 0.0, (from == 0 ? 1.0 : -1.0) * std::cos(angle));
    const std::vector<InterfaceAlbedo> single = single_scattering_albedo(interface, wi);
    for (std::size_t k = 0; k < n; ++k) {
      const double rest = std::max(0.0, single[k].loss());
      reflect_target[from].push_back(rest * (1.0 - sides_[from].share[k]));
      transmit_target[from].push_back(rest * sides_[from].share[k]);
    }
  }
  // The table's values between each grid angle and the exit quadrature's cosines, and where those fall on the grid.
  const QuadratureRule u = gauss_legendre(96, 0.0, 1.0);
  const std::size_t q_count = static_cast<std::size_t>(u.size());
  std::vector<double> exit_mu(q_count);
  for (std::size_t q = 0; q < q_count; ++q) exit_mu[q] = std::sqrt(u.nodes[static_cast<int>(q)]);
  std::array<std::vector<double>, 2> reflection_values, transmission_values;  // [side][k * q_count + q]
  for (std::size_t from = 0; from < 2; ++from) {
    for (std::size_t k = 0; k < n; ++k) {
      const double mu = std::cos(angles_[k]);
      for (std::size_t q = 0; q < q_count; ++q) {
        reflection_values[from].push_back(kPi * u.weights[static_cast<int>(q)] *
                                          symmetric_reflection(from == 0, mu, exit_mu[q]));
        transmission_values[from].push_back(kPi * u.weights[static_cast<int>(q)] *
                                            (from == 0 ? symmetric_transmission(mu, exit_mu[q])
                                                       : symmetric_transmission(exit_mu[q], mu) / (eta_ * eta_)));
      }
    }
  }
  // Per grid angle, int f mu_o d omega_o with the factors `own` at the incident end and `exit` at the other.
  const auto energies = [&](const std::vector<double>& values, const std::vector<double>& own,
                            const std::vector<double>& exit) {
    std::vector<double> energy(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      for (std::size_t q = 0; q < q_count; ++q) energy[k] += values[k * q_count + q] * scale(exit, exit_mu[q]);
      energy[k] *= own[k];
    }
    return energy;
  };
  // d_k <- d_k sqrt(target_k / energy_k): for the reflection, d on both ends; for the transmission, each side's factor
  // on its own end, the two updated together (the mean of their disagreement, where the targets are inconsistent).
  // A factor is held to at most kMaxScale: where the table holds almost nothing at an angle (the walk's few multiply
  // scattered paths at the smallest sigma), a large factor there would spread, interpolated in angle, over its
  // neighbours; the solver matches its node operators' energy on its own (interface_operators.h).
  static constexpr double kMaxScale = 4.0;
  const auto update = [](std::vector<double>& factors, const std::vector<double>& energy,
                         const std::vector<double>& target) {
    double residual = 0.0;
    for (std::size_t k = 0; k < factors.size(); ++k) {
      if (target[k] <= 0.0 || energy[k] <= 0.0) {
        factors[k] = target[k] <= 0.0 ? 0.0 : factors[k];
        continue;
      }
      const double scaled = factors[k] * std::sqrt(target[k] / energy[k]);
      if (scaled < kMaxScale) residual = std::max(residual, std::abs(energy[k] / target[k] - 1.0));
      factors[k] = std::min(scaled, kMaxScale);
    }
    return residual;
  };
  for (std::size_t from = 0; from < 2; ++from) {
    std::vector<double>& r = sides_[from].reflection_scale;
    for (int step = 0; step < kMaxSteps; ++step) {
      if (update(r, energies(reflection_values[from], r, r), reflect_target[from]) < kTolerance) break;
    }
  }
  std::vector<double>& above = sides_[0].transmission_scale;
  std::vector<double>& below = sides_[1].transmission_scale;
  for (int step = 0; step < kMaxSteps; ++step) {
    const std::vector<double> from_above = energies(transmission_values[0], above, below);
    const std::vector<double> from_below = energies(transmission_values[1], below, above);
    std::vector<double> old_above = above, old_below = below;
    update(above, from_above, transmit_target[0]);
    update(below, from_below, transmit_target[1]);
    double change = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      if (old_above[k] > 0.0 && old_below[k] > 0.0) {
        change = std::max(change, std::abs(above[k] * below[k] / (old_above[k] * old_below[k]) - 1.0));
      }
    }
    if (change < kTolerance) break;
  }
}

double MultipleScatteringLobe::scale(const std::vector<double>& factors, double mu) const {
  const auto [i, w] = node(mu);
  return (1.0 - w) * factors[i] + w * factors[i + 1];
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

double MultipleScatteringLobe::symmetric_reflection(bool from_above, double mu_i, double mu_o) const {
  return 0.5 * (raw_reflection(from_above, mu_i, mu_o) + raw_reflection(from_above, mu_o, mu_i));
}

double MultipleScatteringLobe::symmetric_transmission(double mu_above, double mu_below) const {
  return 0.5 * (raw_transmission(true, mu_above, mu_below) + eta_ * eta_ * raw_transmission(false, mu_below, mu_above));
}

double MultipleScatteringLobe::reflection(bool from_above, double mu_i, double mu_o) const {
  const std::vector<double>& r = sides_[from_above ? 0 : 1].reflection_scale;
  return scale(r, mu_i) * symmetric_reflection(from_above, mu_i, mu_o) * scale(r, mu_o);
}

double MultipleScatteringLobe::transmission(bool from_above, double mu_i, double mu_o) const {
  if (!from_above) return transmission(true, mu_o, mu_i) / (eta_ * eta_);
  return scale(sides_[0].transmission_scale, mu_i) * symmetric_transmission(mu_i, mu_o) *
         scale(sides_[1].transmission_scale, mu_o);
}

double MultipleScatteringLobe::transmitted_share(bool from_above, double mu_i) const {
  const Side& side = sides_[from_above ? 0 : 1];
  const auto [i, w] = node(mu_i);
  return (1.0 - w) * side.share[i] + w * side.share[i + 1];
}

}  // namespace skinlayer
