#include "app/render/material_solve.h"

#include <algorithm>
#include <chrono>

namespace skinlayer {

ColorTables solve_color(const ColorMaterial& material, double theta_i) {
  const auto start = std::chrono::steady_clock::now();
  ColorTables result;
  result.material = material;
  result.albedo_theta_i = theta_i;
  // One solve for the distinct albedo values; the channels index into it.
  std::vector<double> distinct;
  std::array<std::size_t, 3> index{};
  for (int c = 0; c < 3; ++c) {
    const auto found = std::find(distinct.begin(), distinct.end(), material.albedo_rgb[c]);
    index[c] = static_cast<std::size_t>(found - distinct.begin());
    if (found == distinct.end()) distinct.push_back(material.albedo_rgb[c]);
  }
  const std::vector<LayerTables> tables = solve(material.layer, distinct);
  const std::vector<std::vector<DirectionalAlbedo>> albedo =
      directional_albedo(material.layer, std::vector<double>{theta_i}, distinct);
  for (int c = 0; c < 3; ++c) {
    result.channels[c] = tables[index[c]];
    result.albedo[c] = albedo[index[c]].front();
  }
  result.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

double brdf_total(const ColorTables& tables, int channel, double theta_i, double theta_o, double phi) {
  return brdf_surface(tables.material.layer, theta_i, theta_o, phi) +
         tables.channels[channel].brdf_subsurface(theta_i, theta_o, phi);
}

double btdf_total(const ColorTables& tables, int channel, double theta_i, double theta_o, double phi) {
  return tables.channels[channel].btdf(theta_i, theta_o, phi);
}

}  // namespace skinlayer
