// docs/model.md §21.15: the entering radiance, continuous in the polar angle.
#include "core/spatial/entering_radiance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"

namespace skinlayer {

EnteringRadiance::EnteringRadiance(const LateralTopInterface& top, const std::optional<RoughDielectric>& rough,
                                   int ordinates)
    : collimated_(top.collimated) {
  if (top.source.size() != ordinates) throw std::invalid_argument("EnteringRadiance: the top has another resolution");
  const QuadratureRule q = double_gauss_half_range(ordinates);
  const bool lobe = rough && top.source_single.size() == ordinates;
  if (lobe) {
    lobe_ = *rough;
    lobe_width_ = refracted_lobe_width(*rough);
  }
  // The nodes ascending in mu (double_gauss_half_range's order is not assumed).
  std::vector<int> order(static_cast<std::size_t>(ordinates));
  for (int j = 0; j < ordinates; ++j) order[static_cast<std::size_t>(j)] = j;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return q.nodes[a] < q.nodes[b]; });
  for (const int j : order) {
    nodes_.push_back(q.nodes[static_cast<std::size_t>(j)]);
    broad_.push_back(top.source(j) - (lobe ? top.source_single(j) : 0.0));
  }
  if (top.source.isZero()) return;
  const QuadratureRule theta = gauss_legendre_panels(graded_panels(0.0, 0.5 * kPi, lobe ? lobe_width_ : 0.0, 0.25), 8);
  if (lobe && has_multiple_scattering(*rough)) {
    // The lobe's flux on the directions below, scaled to the nodes' (the sums' common 2 pi left out).
    multiple_ = top.multiple != nullptr ? top.multiple : std::make_shared<const MultipleScatteringLobe>(*rough, 1);
    double nodes_flux = 0.0, lobe_flux = 0.0;
    for (int j = 0; j < ordinates; ++j) {
      nodes_flux += q.weights[static_cast<std::size_t>(j)] * q.nodes[static_cast<std::size_t>(j)] *
                    (top.source(j) - top.source_single(j));
    }
    for (int p = 0; p < theta.size(); ++p) {
      const double mu = std::cos(theta.nodes[p]);
      lobe_flux += mu * multiple_transmission_from_normal(mu) * std::sin(theta.nodes[p]) * theta.weights[p];
    }
    multiple_scale_ = lobe_flux > 0.0 ? nodes_flux / lobe_flux : 0.0;
  }
  for (int p = 0; p < theta.size(); ++p) {
    const double mu = std::cos(theta.nodes[p]);
    const double power = 2.0 * kPi * mu * (*this)(mu)*std::sin(theta.nodes[p]) * theta.weights[p];
    if (power <= 0.0) continue;
    directions_.nodes.push_back(mu);
    directions_.weights.push_back(power);
  }
}

double EnteringRadiance::operator()(double mu) const {
  double value = 0.0;
  if (lobe_) {
    const double sine = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    value += microfacet_btdf(*lobe_, Vec3(0.0, 0.0, 1.0), Vec3(sine, 0.0, -mu));
  }
  if (multiple_) return value + multiple_scale_ * multiple_transmission_from_normal(mu);
  // The broad part, linear between the nodes, held beyond the end ones.
  if (mu <= nodes_.front()) return value + broad_.front();
  if (mu >= nodes_.back()) return value + broad_.back();
  const std::size_t hi = static_cast<std::size_t>(std::upper_bound(nodes_.begin(), nodes_.end(), mu) - nodes_.begin());
  const double t = (mu - nodes_[hi - 1]) / (nodes_[hi] - nodes_[hi - 1]);
  return value + (1.0 - t) * broad_[hi - 1] + t * broad_[hi];
}

double EnteringRadiance::multiple_transmission_from_normal(double mu) const {
  return std::max(0.0, multiple_->transmission_at(true, 1.0, mu, 0.0));  // uniform in azimuth from the normal
}

}  // namespace skinlayer
