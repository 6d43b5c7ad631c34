// The parameter sets `skinlayer validate` checks the solver on against the Monte Carlo reference: the paper's figure
// settings, then one family per parameter around them (g, Omega, sigma, eta, the bottom, the depth), so that every
// value the check names appears at least once: g in {0, 0.5, 0.9}, Omega in {0.5, 0.99, 1}, sigma in {0.1, 0.5, 1},
// eta in {1, 1.4, 2}, thin and semi-infinite layers, and each bottom (air, matched, lambert).
//
// Left out on purpose: Omega = 1 with T = 0. A random walk in a conservative half-space returns with probability 1
// but after a number of collisions whose mean diverges, so any cut-off walk is biased; the solver's semi-infinite
// conservative case is checked against the H-function instead (tests/core/solver_limits_test.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/material.h"

namespace skinlayer::validation {

struct ValidationSet {
  std::string name;         // file stem and table key, e.g. "paper-default"
  std::string description;  // what the set covers, one line
  Material material;
  double theta_i_deg = 45.0;
  std::uint64_t paths = 0;        // Monte Carlo paths of a full run
  std::uint64_t quick_paths = 0;  // and of a quick run (CI): a few seconds per set on 2 cores
  std::size_t grid_index = 0;     // position in validation_grid()
};

std::vector<ValidationSet> validation_grid();

}  // namespace skinlayer::validation
