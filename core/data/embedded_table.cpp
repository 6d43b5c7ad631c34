#include "core/data/embedded_table.h"

#include <algorithm>

namespace skinlayer::data {

double EmbeddedTable::interpolate(int column, double x) const {
  const int n = rows();
  if (x <= at(0, 0)) return at(0, column);
  if (x >= at(n - 1, 0)) return at(n - 1, column);
  int lo = 0, hi = n - 1;  // at(lo, 0) < x < at(hi, 0)
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    (at(mid, 0) <= x ? lo : hi) = mid;
  }
  const double t = (x - at(lo, 0)) / (at(hi, 0) - at(lo, 0));
  return (1.0 - t) * at(lo, column) + t * at(hi, column);
}

}  // namespace skinlayer::data
