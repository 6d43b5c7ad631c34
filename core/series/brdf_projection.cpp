// docs/model.md §22.6: a BRDF's Fourier coefficients on the tables' grid.
#include "core/series/brdf_projection.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/conventions.h"

namespace skinlayer {

std::array<LayerTables, 3> project_brdf(const RgbBrdf& brdf, int grid_size, int modes,
                                        const ParallelFor& parallel_for) {
  if (grid_size < 4 || modes < 1) throw std::invalid_argument("project_brdf: needs grid_size >= 4 and modes >= 1");
  const int samples = 4 * modes;
  const auto k = static_cast<std::size_t>(grid_size);
  const std::size_t size = k * k * static_cast<std::size_t>(modes);
  std::array<std::vector<double>, 3> coefficients;
  for (std::vector<double>& channel : coefficients) channel.assign(size, 0.0);
  run_parallel(parallel_for, grid_size, [&](int i) {
    const double theta_i = LayerTables::grid_angle(i, grid_size);
    std::vector<Eigen::Array3d> values(static_cast<std::size_t>(samples));
    for (int o = 0; o < grid_size; ++o) {
      const double theta_o = LayerTables::grid_angle(o, grid_size);
      for (int j = 0; j < samples; ++j) {
        values[static_cast<std::size_t>(j)] = brdf(theta_i, theta_o, 2.0 * kPi * j / samples);
      }
      for (int m = 0; m < modes; ++m) {
        Eigen::Array3d sum = Eigen::Array3d::Zero();
        for (int j = 0; j < samples; ++j) {
          sum += values[static_cast<std::size_t>(j)] * std::cos(2.0 * kPi * m * j / samples);
        }
        const double scale = (m == 0 ? 1.0 : 2.0) / samples;
        const std::size_t at =
            (static_cast<std::size_t>(m) * k + static_cast<std::size_t>(i)) * k + static_cast<std::size_t>(o);
        for (int c = 0; c < 3; ++c) coefficients[static_cast<std::size_t>(c)][at] = scale * sum(c);
      }
    }
  });
  return {LayerTables(grid_size, modes, std::move(coefficients[0]), std::vector<double>(size, 0.0)),
          LayerTables(grid_size, modes, std::move(coefficients[1]), std::vector<double>(size, 0.0)),
          LayerTables(grid_size, modes, std::move(coefficients[2]), std::vector<double>(size, 0.0))};
}

}  // namespace skinlayer
