#include "app/render/material_solve.h"

#include <chrono>
#include <cmath>

#include "core/conventions.h"
#include "core/series/quadrature.h"

namespace skinlayer {

namespace {

// A comparison model's directional albedo: its tables' mode 0 integrated over the outgoing hemisphere,
//   R_sub = 2 pi int_0^{pi/2} S_0(theta_i, theta) cos(theta) sin(theta) d theta  (likewise T from B_0),
// with the layer's surface reflectance (the surface term is shared) and interface loss left out.
DirectionalAlbedo model_albedo(const LayerTables& tables, const DirectionalAlbedo& layer) {
  const QuadratureRule theta = gauss_legendre(64, 0.0, 0.5 * kPi);
  DirectionalAlbedo row = layer;
  row.reflectance_subsurface = 0.0;
  row.transmittance = 0.0;
  for (int a = 0; a < theta.size(); ++a) {
    const double t = theta.nodes[a];
    const double weight = 2.0 * kPi * theta.weights[a] * std::cos(t) * std::sin(t);
    row.reflectance_subsurface += weight * tables.reflection_mode(0, layer.theta_i, t);
    row.transmittance += weight * tables.transmission_mode(0, layer.theta_i, t);
  }
  row.interface_loss = 0.0;
  row.absorptance = 1.0 - row.reflectance() - row.transmittance;
  return row;
}

}  // namespace

MaterialDocument material_document(const ColorMaterial& material) {
  MaterialDocument document;
  document.layer = material.layer;
  document.set_layer_albedo(0, material.albedo_rgb);
  for (std::size_t i = 0; i < material.layer.below.size(); ++i) {
    document.set_layer_albedo(i + 1, i < material.below_rgb.size() ? material.below_rgb[i] : AlbedoRgb{1.0, 1.0, 1.0});
  }
  document.model = material.model;
  return document;
}

ColorMaterial color_material(const MaterialDocument& document) {
  require_layered(document, "render, export and the previewer");
  return ColorMaterial{document.layer, document.albedo_rgb, document.below_rgb,
                       document.model.value_or(SubsurfaceModel::Stam)};
}

ColorTables solve_color(const ColorMaterial& material, double theta_i, const SolveOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ColorTables result;
  result.material = material;
  result.albedo_theta_i = theta_i;
  // One solve for the distinct channels (each its layers' albedos); the channels index into it.
  const DistinctChannels channels = distinct_channels(material_document(material));
  const std::vector<Material>& distinct = channels.materials;
  std::vector<LayerTables> tables;
  std::vector<DirectionalAlbedo> albedo;
  const std::vector<std::vector<DirectionalAlbedo>> layer_albedo =
      directional_albedo(distinct, std::vector<double>{theta_i}, options);
  if (material.model == SubsurfaceModel::Stam) {
    tables = solve(distinct, options);
    for (const std::vector<DirectionalAlbedo>& rows : layer_albedo) albedo.push_back(rows.front());
  } else {
    for (std::size_t d = 0; d < distinct.size(); ++d) {
      tables.push_back(solve_model(distinct[d], material.model, options));
      albedo.push_back(model_albedo(tables.back(), layer_albedo[d].front()));
    }
  }
  for (int c = 0; c < 3; ++c) {
    result.channels[c] = tables[channels.index[c]];
    result.albedo[c] = albedo[channels.index[c]];
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
