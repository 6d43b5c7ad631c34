#include "app/render/material_solve.h"

#include <chrono>

namespace skinlayer {

ColorTables solve_color(const ColorMaterial& material, double theta_i) {
  const auto start = std::chrono::steady_clock::now();
  ColorTables result;
  result.material = material;
  result.albedo_theta_i = theta_i;
  for (int c = 0; c < 3; ++c) {
    int same = -1;
    for (int d = 0; d < c; ++d) {
      if (material.albedo_rgb[d] == material.albedo_rgb[c]) same = d;
    }
    if (same >= 0) {
      result.channels[c] = result.channels[same];
      result.albedo[c] = result.albedo[same];
      continue;
    }
    Material layer = material.layer;
    layer.albedo = material.albedo_rgb[c];
    result.channels[c] = solve(layer);
    result.albedo[c] = directional_albedo(layer, std::vector<double>{theta_i})[0];
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
