// Cycles' table reads (docs/model.md §22.1.1): a table returns its nodes, is linear between them along each axis,
// reproduces any multilinear function exactly, and clamps its coordinates to [0, 1].
#include "core/targets/cycles_lookup_table.h"

#include <gtest/gtest.h>

namespace skinlayer {
namespace {

// f(x, y, z) = 1 + 2x + 3y + 5z + 7xy + 11yz + 13xz + 17xyz on the nodes' coordinates k / (n - 1).
double multilinear(double x, double y, double z) {
  return 1.0 + 2.0 * x + 3.0 * y + 5.0 * z + 7.0 * x * y + 11.0 * y * z + 13.0 * x * z + 17.0 * x * y * z;
}

TEST(CyclesLookupTable, ReproducesMultilinearFunctionsAndClamps) {
  const int nx = 5, ny = 4, nz = 3;
  const CyclesLookupTable table(nx, ny, nz, [&](int x, int y, int z) {
    return multilinear(x / double(nx - 1), y / double(ny - 1), z / double(nz - 1));
  });
  EXPECT_EQ(table.node(2, 1, 1), multilinear(0.5, 1.0 / 3.0, 0.5));
  for (const double x : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    for (const double y : {0.0, 0.2, 0.9, 1.0}) {
      for (const double z : {0.0, 0.31, 1.0}) EXPECT_NEAR(table.read(x, y, z), multilinear(x, y, z), 1e-12);
    }
  }
  EXPECT_NEAR(table.read(-0.5, 2.0, 1.5), multilinear(0.0, 1.0, 1.0), 1e-12);

  const CyclesLookupTable row(3, 1, 1, [](int x, int, int) { return x * x; });  // 0, 1, 4
  EXPECT_EQ(row.read(0.5), 1.0);
  EXPECT_NEAR(row.read(0.75), 2.5, 1e-15);  // linear between nodes, not the parabola
  const CyclesLookupTable sheet(2, 3, 1, [](int x, int y, int) { return 10.0 * y + x; });
  EXPECT_NEAR(sheet.read(0.25, 0.75), 15.25, 1e-12);
}

TEST(CyclesLookupTable, NodeCoordinatesAreClampedLikeCyclesGenerator) {
  EXPECT_EQ(cycles_node_coordinate(0, 32, 1e-4, 1.0), 1e-4);
  EXPECT_EQ(cycles_node_coordinate(31, 32, 1e-4, 1.0), 1.0);
  EXPECT_EQ(cycles_node_coordinate(15, 16, 1e-4, 0.99), 0.99);
  EXPECT_NEAR(cycles_node_coordinate(3, 16, 1e-4, 0.99), 0.2, 1e-15);
}

}  // namespace
}  // namespace skinlayer
