#include "core/sampling/piecewise_linear_2d.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace skinlayer {
namespace {

// The largest i in [0, size - 2] with below(i) true (below is true at 0 and monotone); the cell a CDF value lies in.
template <typename Below>
int find_interval(int size, const Below& below) {
  int first = 1, length = size - 2;
  while (length > 0) {
    const int half = length / 2, middle = first + half;
    if (below(middle)) {
      first = middle + 1;
      length -= half + 1;
    } else {
      length = half;
    }
  }
  return std::clamp(first - 1, 0, size - 2);
}

// Within a cell whose density runs linearly from a to b over [0, 1], the t whose integral a t + (b - a) t^2 / 2 is
// `area`; the linear case when a and b nearly agree (the same test pbrt-v4 and Mitsuba make).
double invert_linear(double a, double b, double area) {
  if (std::abs(a - b) < 1e-4 * (a + b)) return a > 0.0 ? area / a : 0.0;
  return (a - std::sqrt(std::max(a * a + 2.0 * area * (b - a), 0.0))) / (a - b);
}

}  // namespace

PiecewiseLinear2D::PiecewiseLinear2D(std::span<const double> values, int nx, int ny,
                                     std::vector<std::vector<double>> params)
    : nx_(nx), ny_(ny), params_(std::move(params)) {
  if (nx < 2 || ny < 2) throw std::invalid_argument("PiecewiseLinear2D: the grid needs at least 2 x 2 nodes");
  if (params_.size() > 2) throw std::invalid_argument("PiecewiseLinear2D: at most two parameters");
  std::size_t slices = 1;
  for (const std::vector<double>& p : params_) {
    if (p.empty() || !std::is_sorted(p.begin(), p.end())) {
      throw std::invalid_argument("PiecewiseLinear2D: a parameter's nodes must be ascending and not empty");
    }
    slices *= p.size();
  }
  const std::size_t n = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  if (values.size() != slices * n) {
    throw std::invalid_argument("PiecewiseLinear2D: " + std::to_string(values.size()) + " values for " +
                                std::to_string(slices) + " slices of " + std::to_string(n));
  }
  data_.resize(values.size());
  conditional_.resize(values.size());
  marginal_.resize(slices * static_cast<std::size_t>(ny));
  for (std::size_t s = 0; s < slices; ++s) {
    const double* d = values.data() + s * n;
    double* c = conditional_.data() + s * n;
    double* m = marginal_.data() + s * static_cast<std::size_t>(ny);
    for (std::size_t i = 0; i < n; ++i) {
      if (!(d[i] >= 0.0) || !std::isfinite(d[i])) {
        throw std::invalid_argument("PiecewiseLinear2D: value " + std::to_string(d[i]) + " is negative or not finite");
      }
    }
    for (int y = 0; y < ny; ++y) {
      const std::size_t row = static_cast<std::size_t>(y) * nx;
      c[row] = 0.0;
      for (int x = 0; x + 1 < nx; ++x) c[row + x + 1] = c[row + x] + 0.5 * (d[row + x] + d[row + x + 1]);
    }
    m[0] = 0.0;
    for (int y = 0; y + 1 < ny; ++y) {
      m[y + 1] =
          m[y] + 0.5 * (c[(static_cast<std::size_t>(y) + 1) * nx - 1] + c[(static_cast<std::size_t>(y) + 2) * nx - 1]);
    }
    const double total = m[ny - 1];
    if (!(total > 0.0)) throw std::invalid_argument("PiecewiseLinear2D: a slice integrates to 0");
    for (std::size_t i = 0; i < n; ++i) {
      data_[s * n + i] = d[i] / total;
      c[i] /= total;
    }
    for (int y = 0; y < ny; ++y) m[y] /= total;
  }
}

PiecewiseLinear2D::Blend PiecewiseLinear2D::blend(std::span<const double> param) const {
  if (param.size() != params_.size()) {
    throw std::invalid_argument("PiecewiseLinear2D: " + std::to_string(param.size()) + " parameters for a table of " +
                                std::to_string(params_.size()));
  }
  Blend b;
  b.offset[0] = 0;
  b.weight[0] = 1.0;
  std::size_t stride = 1;  // slices per step of the current parameter (the last parameter fastest)
  for (std::size_t d = params_.size(); d-- > 0;) {
    const std::vector<double>& nodes = params_[d];
    const int size = static_cast<int>(nodes.size());
    int k = 0;
    double w = 0.0;
    if (size > 1) {
      k = find_interval(size, [&](int i) { return nodes[static_cast<std::size_t>(i)] <= param[d]; });
      w = std::clamp((param[d] - nodes[k]) / (nodes[k + 1] - nodes[k]), 0.0, 1.0);
    }
    const int count = b.count;
    for (int i = 0; i < count; ++i) {
      b.offset[i + count] = b.offset[i] + (static_cast<std::size_t>(k) + 1) * stride;
      b.weight[i + count] = b.weight[i] * w;
      b.offset[i] += static_cast<std::size_t>(k) * stride;
      b.weight[i] *= 1.0 - w;
    }
    b.count = count * 2;
    stride *= nodes.size();
  }
  return b;
}

double PiecewiseLinear2D::lookup(const std::vector<double>& table, std::size_t per_slice, const Blend& b,
                                 std::size_t i) {
  double sum = 0.0;
  for (int k = 0; k < b.count; ++k) sum += b.weight[k] * table[b.offset[k] * per_slice + i];
  return sum;
}

double PiecewiseLinear2D::eval(std::array<double, 2> u, std::span<const double> param) const {
  const Blend b = blend(param);
  const double px = std::clamp(u[0], 0.0, 1.0) * (nx_ - 1), py = std::clamp(u[1], 0.0, 1.0) * (ny_ - 1);
  const int x = std::min(static_cast<int>(px), nx_ - 2), y = std::min(static_cast<int>(py), ny_ - 2);
  const double sx = px - x, sy = py - y;
  const std::size_t i = static_cast<std::size_t>(y) * nx_ + x;
  const double v00 = lookup(data_, cells(), b, i), v10 = lookup(data_, cells(), b, i + 1);
  const double v01 = lookup(data_, cells(), b, i + nx_), v11 = lookup(data_, cells(), b, i + nx_ + 1);
  const double value = (1.0 - sy) * ((1.0 - sx) * v00 + sx * v10) + sy * ((1.0 - sx) * v01 + sx * v11);
  return value * (nx_ - 1) * (ny_ - 1);
}

PiecewiseLinear2D::Sample PiecewiseLinear2D::sample(std::array<double, 2> xi, std::span<const double> param) const {
  const Blend b = blend(param);
  const std::size_t nx = static_cast<std::size_t>(nx_);
  // The row: invert the marginal CDF, whose density (the row sums) is linear in y within a cell.
  double sy = std::clamp(xi[1], 0.0, 1.0);
  const int y = find_interval(ny_, [&](int k) { return lookup(marginal_, ny_, b, static_cast<std::size_t>(k)) <= sy; });
  const double r0 = lookup(conditional_, cells(), b, (static_cast<std::size_t>(y) + 1) * nx - 1);
  const double r1 = lookup(conditional_, cells(), b, (static_cast<std::size_t>(y) + 2) * nx - 1);
  sy -= lookup(marginal_, ny_, b, static_cast<std::size_t>(y));
  const double t = std::clamp(invert_linear(r0, r1, sy), 0.0, 1.0);
  // The column: invert the row CDF interpolated between the two rows at t.
  const std::size_t row0 = static_cast<std::size_t>(y) * nx, row1 = row0 + nx;
  double sx = std::clamp(xi[0], 0.0, 1.0) * ((1.0 - t) * r0 + t * r1);
  const auto cdf = [&](std::size_t k) {
    return (1.0 - t) * lookup(conditional_, cells(), b, row0 + k) + t * lookup(conditional_, cells(), b, row1 + k);
  };
  const int x = find_interval(nx_, [&](int k) { return cdf(static_cast<std::size_t>(k)) <= sx; });
  const std::size_t xs = static_cast<std::size_t>(x);
  const double c0 = (1.0 - t) * lookup(data_, cells(), b, row0 + xs) + t * lookup(data_, cells(), b, row1 + xs);
  const double c1 = (1.0 - t) * lookup(data_, cells(), b, row0 + xs + 1) + t * lookup(data_, cells(), b, row1 + xs + 1);
  sx -= cdf(xs);
  const double s = std::clamp(invert_linear(c0, c1, sx), 0.0, 1.0);
  return {{(x + s) / (nx_ - 1), (y + t) / (ny_ - 1)}, ((1.0 - s) * c0 + s * c1) * (nx_ - 1) * (ny_ - 1)};
}

PiecewiseLinear2D::Sample PiecewiseLinear2D::invert(std::array<double, 2> u, std::span<const double> param) const {
  const Blend b = blend(param);
  const std::size_t nx = static_cast<std::size_t>(nx_);
  const double px = std::clamp(u[0], 0.0, 1.0) * (nx_ - 1), py = std::clamp(u[1], 0.0, 1.0) * (ny_ - 1);
  const int x = std::min(static_cast<int>(px), nx_ - 2), y = std::min(static_cast<int>(py), ny_ - 2);
  const double s = px - x, t = py - y;
  const std::size_t row0 = static_cast<std::size_t>(y) * nx, row1 = row0 + nx, xs = static_cast<std::size_t>(x);
  const double c0 = (1.0 - t) * lookup(data_, cells(), b, row0 + xs) + t * lookup(data_, cells(), b, row1 + xs);
  const double c1 = (1.0 - t) * lookup(data_, cells(), b, row0 + xs + 1) + t * lookup(data_, cells(), b, row1 + xs + 1);
  const bool flat_x = std::abs(c0 - c1) < 1e-4 * (c0 + c1);
  double xi_x = flat_x ? c0 * s : s * (c0 + 0.5 * s * (c1 - c0));
  xi_x += (1.0 - t) * lookup(conditional_, cells(), b, row0 + xs) + t * lookup(conditional_, cells(), b, row1 + xs);
  const double r0 = lookup(conditional_, cells(), b, row1 - 1), r1 = lookup(conditional_, cells(), b, row1 + nx - 1);
  const double row_total = (1.0 - t) * r0 + t * r1;
  xi_x = row_total > 0.0 ? xi_x / row_total : 0.0;
  const bool flat_y = std::abs(r0 - r1) < 1e-4 * (r0 + r1);
  double xi_y = flat_y ? r0 * t : t * (r0 + 0.5 * t * (r1 - r0));
  xi_y += lookup(marginal_, ny_, b, static_cast<std::size_t>(y));
  return {{xi_x, xi_y}, ((1.0 - s) * c0 + s * c1) * (nx_ - 1) * (ny_ - 1)};
}

}  // namespace skinlayer
