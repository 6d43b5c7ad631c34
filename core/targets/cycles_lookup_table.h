// A table read the way Cycles reads its precomputed tables (kernel/util/lookup_table.h, lookup_table_read and its
// _2D and _3D forms, Blender 4.x-5.x), for the tables the Principled BSDF's energy compensation and layering use
// (docs/model.md §22.1.1). Along each axis of n nodes the coordinate u in [0, 1] (clamped) falls at u (n - 1); the
// node below is k = floor, the one above min(k + 1, n - 1), and the value is linear between them; the axes are
// interpolated in turn (bilinear, trilinear). Node k sits at k / (n - 1); Cycles' generator
// (app/cycles_precompute.cpp) evaluates it at that coordinate clamped away from the ends, which
// `cycles_node_coordinate` gives.
#pragma once

#include <functional>
#include <vector>

namespace skinlayer {

class CyclesLookupTable {
 public:
  // A table of nx x ny x nz nodes (ny = nz = 1 for one dimension, nz = 1 for two) filled by value(x, y, z), called
  // with each node's indices. The x index runs fastest, as in Cycles' arrays.
  CyclesLookupTable(int nx, int ny, int nz, const std::function<double(int x, int y, int z)>& value);

  double read(double x) const;                      // 1D
  double read(double x, double y) const;            // 2D
  double read(double x, double y, double z) const;  // 3D
  double node(int x, int y = 0, int z = 0) const;

 private:
  double read_row(double x, int row) const;  // a row of nx values, row = y + ny z
  double read_slab(double x, double y, int slab) const;

  int nx_, ny_, nz_;
  std::vector<double> values_;
};

// The coordinate of node k of n on [0, 1] as Cycles' generator clamps it: clamp(k / (n - 1), lo, hi).
double cycles_node_coordinate(int k, int n, double lo, double hi);

}  // namespace skinlayer
