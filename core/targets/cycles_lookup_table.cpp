// docs/model.md §22.1.1: Cycles' interpolated table reads.
#include "core/targets/cycles_lookup_table.h"

#include <algorithm>
#include <cmath>

namespace skinlayer {
namespace {

// The node below u (clamped to [0, 1]) on n nodes, its neighbour above and the weight of that neighbour.
struct Bracket {
  int below, above;
  double t;
};
Bracket bracket(double u, int n) {
  const double position = std::clamp(u, 0.0, 1.0) * (n - 1);
  const int below = std::min(static_cast<int>(position), n - 1);
  return {below, std::min(below + 1, n - 1), position - below};
}

}  // namespace

CyclesLookupTable::CyclesLookupTable(int nx, int ny, int nz, const std::function<double(int, int, int)>& value)
    : nx_(nx), ny_(ny), nz_(nz), values_(static_cast<std::size_t>(nx) * ny * nz) {
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) values_[static_cast<std::size_t>((z * ny + y) * nx + x)] = value(x, y, z);
}

double CyclesLookupTable::node(int x, int y, int z) const {
  return values_[static_cast<std::size_t>((z * ny_ + y) * nx_ + x)];
}

double CyclesLookupTable::read_row(double x, int row) const {
  const Bracket b = bracket(x, nx_);
  const double below = values_[static_cast<std::size_t>(row * nx_ + b.below)];
  if (b.t == 0.0) return below;
  return (1.0 - b.t) * below + b.t * values_[static_cast<std::size_t>(row * nx_ + b.above)];
}

double CyclesLookupTable::read_slab(double x, double y, int slab) const {
  const Bracket b = bracket(y, ny_);
  const double below = read_row(x, slab * ny_ + b.below);
  if (b.t == 0.0) return below;
  return (1.0 - b.t) * below + b.t * read_row(x, slab * ny_ + b.above);
}

double CyclesLookupTable::read(double x) const { return read_row(x, 0); }

double CyclesLookupTable::read(double x, double y) const { return read_slab(x, y, 0); }

double CyclesLookupTable::read(double x, double y, double z) const {
  const Bracket b = bracket(z, nz_);
  const double below = read_slab(x, y, b.below);
  if (b.t == 0.0) return below;
  return (1.0 - b.t) * below + b.t * read_slab(x, y, b.above);
}

double cycles_node_coordinate(int k, int n, double lo, double hi) {
  return std::clamp(static_cast<double>(k) / (n - 1), lo, hi);
}

}  // namespace skinlayer
