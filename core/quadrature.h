// Polar-angle quadrature: Gauss-Legendre rules and the double-Gauss rule of discrete-ordinate codes.
#pragma once

#include <vector>

namespace skinlayer {

struct QuadratureRule {
  std::vector<double> nodes;
  std::vector<double> weights;
  int size() const { return static_cast<int>(nodes.size()); }
};

// n-point Gauss-Legendre rule on [a, b]: exact for polynomials of degree <= 2n - 1. Nodes ascending.
QuadratureRule gauss_legendre(int n, double a = -1.0, double b = 1.0);

// Double-Gauss (Sykes 1951; DISORT): Gauss-Legendre with n nodes on each half-range mu in (0, 1), weights summing
// to 1. The same cosines serve upward (+mu) and downward (-mu) directions. No node at mu = 0; half-range moments
// int_0^1 mu^k dmu are exact for k <= 2n - 1. Nodes ascending.
QuadratureRule double_gauss_half_range(int n);

}  // namespace skinlayer
