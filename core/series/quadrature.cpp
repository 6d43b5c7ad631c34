#include "core/series/quadrature.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/conventions.h"

namespace skinlayer {

// Newton iteration on P_n from the Tricomi initial guess; P_n and P_n' by the three-term recurrence
// (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}. Weight w = 2 / ((1 - x^2) P_n'(x)^2). (Abramowitz & Stegun 25.4.29.)
QuadratureRule gauss_legendre(int n, double a, double b) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: n must be >= 1");
  QuadratureRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  const double half_length = 0.5 * (b - a);
  const double midpoint = 0.5 * (b + a);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p_prev = 1.0;
      double p = x;
      for (int k = 1; k < n; ++k) {
        const double p_next = ((2.0 * k + 1.0) * x * p - k * p_prev) / (k + 1.0);
        p_prev = p;
        p = p_next;
      }
      if (n == 1) {
        p = x;
        p_prev = 1.0;
      }
      derivative = n * (x * p - p_prev) / (x * x - 1.0);
      const double step = p / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    const double weight = 2.0 / ((1.0 - x * x) * derivative * derivative);
    // Largest root first from the guess; store ascending and symmetric.
    rule.nodes[n - 1 - i] = midpoint + half_length * x;
    rule.nodes[i] = midpoint - half_length * x;
    rule.weights[n - 1 - i] = half_length * weight;
    rule.weights[i] = half_length * weight;
  }
  return rule;
}

std::vector<std::pair<double, double>> graded_panels(double from, double to, double fine, double widest) {
  std::vector<double> breaks = {from, to};
  if (fine > 0.0) {
    for (const double f : {0.5, 1.0, 2.0, 4.0}) breaks.push_back(from + f * fine);
  }
  std::sort(breaks.begin(), breaks.end());
  std::vector<std::pair<double, double>> panels;
  for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
    const double a = breaks[b], c = std::min(breaks[b + 1], to);
    if (!(c > a) || a >= to) continue;
    const int pieces = std::max(1, static_cast<int>(std::ceil((c - a) / widest)));
    for (int p = 0; p < pieces; ++p) panels.emplace_back(a + (c - a) * p / pieces, a + (c - a) * (p + 1) / pieces);
  }
  return panels;
}

QuadratureRule gauss_legendre_panels(std::span<const std::pair<double, double>> panels, int points) {
  const QuadratureRule unit = gauss_legendre(points, 0.0, 1.0);
  QuadratureRule rule;
  for (const auto& [a, b] : panels) {
    for (std::size_t p = 0; p < unit.nodes.size(); ++p) {
      rule.nodes.push_back(a + (b - a) * unit.nodes[p]);
      rule.weights.push_back((b - a) * unit.weights[p]);
    }
  }
  return rule;
}

QuadratureRule double_gauss_half_range(int n) { return gauss_legendre(n, 0.0, 1.0); }

QuadratureRule gauss_hermite(int n) {
  if (n < 1 || n > 100) throw std::invalid_argument("gauss_hermite: n must be in [1, 100]");
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(n, n);
  for (int k = 1; k < n; ++k) jacobi(k, k - 1) = jacobi(k - 1, k) = std::sqrt(0.5 * k);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(jacobi);
  QuadratureRule rule;
  for (int k = 0; k < n; ++k) {
    rule.nodes.push_back(solver.eigenvalues()(k));
    const double v = solver.eigenvectors()(0, k);
    rule.weights.push_back(std::sqrt(kPi) * v * v);
  }
  return rule;
}

}  // namespace skinlayer
