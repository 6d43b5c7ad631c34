// Polar-angle quadrature: Gauss-Legendre rules and the double-Gauss rule of discrete-ordinate codes.
#pragma once

#include <span>
#include <utility>
#include <vector>

namespace skinlayer {

struct QuadratureRule {
  std::vector<double> nodes;
  std::vector<double> weights;
  int size() const { return static_cast<int>(nodes.size()); }
};

// n-point Gauss-Legendre rule on [a, b]: exact for polynomials of degree <= 2n - 1. Nodes ascending.
QuadratureRule gauss_legendre(int n, double a = -1.0, double b = 1.0);

// int_a^b f(x) dx by `unit`, a rule on [0, 1], mapped onto [a, b]: one rule, computed once, serves every interval.
template <class Function>
double integrate_mapped(const QuadratureRule& unit, double a, double b, const Function& f) {
  double total = 0.0;
  for (std::size_t i = 0; i < unit.nodes.size(); ++i) total += unit.weights[i] * f(a + (b - a) * unit.nodes[i]);
  return (b - a) * total;
}

// Panels [a, b) covering [from, to): breaks at from + fine/2, fine, 2 fine and 4 fine when fine > 0 (narrower where a
// lobe starts at `from`), each piece cut further to at most `widest`.
std::vector<std::pair<double, double>> graded_panels(double from, double to, double fine, double widest);

// The composite rule of `points`-point Gauss-Legendre rules on each panel [a, b), nodes in the panels' order.
QuadratureRule gauss_legendre_panels(std::span<const std::pair<double, double>> panels, int points);

// Double-Gauss (Sykes 1951; DISORT): Gauss-Legendre with n nodes on each half-range mu in (0, 1), weights summing
// to 1. The same cosines serve upward (+mu) and downward (-mu) directions. No node at mu = 0; half-range moments
// int_0^1 mu^k dmu are exact for k <= 2n - 1. Nodes ascending.
QuadratureRule double_gauss_half_range(int n);

// n-point Gauss-Hermite rule: int_R e^{-x^2} f(x) dx ~ sum_k w_k f(x_k), exact for polynomials of degree <= 2n - 1
// (Golub & Welsch 1969: nodes are the eigenvalues of the Jacobi matrix with off-diagonal sqrt(k/2), weights
// sqrt(pi) times the squared first components of its unit eigenvectors). Nodes ascending; n <= 100.
QuadratureRule gauss_hermite(int n);

}  // namespace skinlayer
