#include "app/solution/material_solve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "app/material/color_channels.h"
#include "app/solution/skin_comparison.h"
#include "core/conventions.h"
#include "core/series/quadrature.h"
#include "core/series/weighted_tables.h"
#include "core/solve/batch_solve.h"
#include "core/solve/resolution.h"

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
  document.skin = material.skin;
  return document;
}

ColorMaterial color_material(const MaterialDocument& document) {
  return ColorMaterial{document.layer, document.albedo_rgb, document.below_rgb,
                       document.model.value_or(SubsurfaceModel::Stam), document.skin};
}

namespace {

// A skin: one albedo per wavelength of the colour grid (skin_color_wavelengths) and one solve per tabulated
// wavelength, through the warm cache (core/solve/batch_solve.h), on the finest table grid any of them asks for,
// mixed into the three channels. The full solve tabulates every wavelength. The preview (options.preview) tabulates
// only skin_preview_wavelengths (a subset) but still takes every wavelength's albedo (mode 0 alone: cheap), and
// scales each channel's table so that its subsurface reflectance at theta_i is the full grid's: the 50 nm grid alone
// misses hemoglobin's bands at 542 and 577 nm and errs by up to 6% per channel; scaled, the colour on screen while a
// slider moves is the full colour at the light's angle, and only the lobes' shape comes from the coarse grid. The
// layer model only: the comparison models take the skin's RGB (app/solution/skin_comparison.h).
void solve_spectral(const ColorMaterial& material, double theta_i, const SolveOptions& options, ColorTables& result) {
  const MaterialDocument document = material_document(material);
  const ColorChannels full = color_channels(document);
  const bool scaled_preview = options.preview;
  const ColorChannels tabulated = scaled_preview ? color_channels(document, true) : full;
  // tabulated_index[j]: the tables' index of the colour grid's wavelength j, or none.
  std::vector<std::optional<std::size_t>> tabulated_index(full.wavelengths_nm.size());
  std::vector<std::size_t> full_index(tabulated.wavelengths_nm.size());
  for (std::size_t t = 0; t < tabulated.wavelengths_nm.size(); ++t) {
    const auto found = std::ranges::find(full.wavelengths_nm, tabulated.wavelengths_nm[t]);
    if (found == full.wavelengths_nm.end()) throw std::logic_error("the preview's wavelengths are not on the grid");
    full_index[t] = static_cast<std::size_t>(found - full.wavelengths_nm.begin());
    tabulated_index[full_index[t]] = t;
  }
  SolveOptions common = options;
  if (common.table_size == 0) {
    for (const Material& m : tabulated.materials) {
      common.table_size = std::max(common.table_size, choose_resolution(m, options).table_size);
    }
  }
  std::vector<LayerTables> tables(tabulated.materials.size());
  std::vector<DirectionalAlbedo> albedo(full.materials.size());
  const double thetas[1] = {theta_i};
  for_each_with_warm_cache(full.materials.size(), common, [&](std::size_t j, const SolveOptions& one) {
    const Material& m = full.materials[j];
    albedo[j] = directional_albedo(m, thetas, one).front();
    const std::optional<std::size_t> t = tabulated_index[j];
    if (t) tables[*t] = solve(m, one);
  });
  for (int c = 0; c < 3; ++c) {
    result.albedo[c] = mixed_albedo(albedo, full.to_rgb.row(c));
    Eigen::RowVectorXd weights = tabulated.to_rgb.row(c);
    if (scaled_preview) {
      double coarse = 0.0;
      for (std::size_t t = 0; t < full_index.size(); ++t) {
        coarse += weights(static_cast<Eigen::Index>(t)) * albedo[full_index[t]].reflectance_subsurface;
      }
      if (coarse > 0.0) weights *= result.albedo[c].reflectance_subsurface / coarse;
    }
    result.channels[c] = weighted_sum(tables, std::span<const double>(weights.data(), tables.size()));
  }
}

}  // namespace

ColorTables solve_color(const ColorMaterial& material, double theta_i, const SolveOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ColorTables result;
  result.material = material;
  result.albedo_theta_i = theta_i;
  if (material.skin && material.model != SubsurfaceModel::Stam) {
    // The comparison models describe one layer: for a skin, the layer that has its RGB (skin_comparison.h).
    ColorMaterial layer = skin_comparison_layer(material, options).layer;
    layer.model = material.model;
    result = solve_color(layer, theta_i, options);
    result.material = material;  // the surface term and the textures' channels are the skin's
    result.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
  if (material.skin) {
    solve_spectral(material, theta_i, options, result);
    result.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
  // One solve for the distinct channels (each its layers' albedos); the channels index into it.
  const DistinctChannels channels = distinct_channels(material_document(material));
  const std::vector<Material>& distinct = channels.materials;
  std::vector<LayerTables> tables;
  std::vector<DirectionalAlbedo> albedo;
  const std::vector<std::vector<DirectionalAlbedo>> layer_albedo =
      directional_albedo(distinct, std::vector<double>{theta_i}, options);
  if (material.model == SubsurfaceModel::Stam) {
    // Each channel its own solve, at the resolution it needs (its table size may differ), as eval's channels are:
    // every channel is then its grey solve exactly, which one solve of the channels together, sharing the darkest
    // channel's resolution and the modes of the slowest to converge, is not.
    tables = solve_batch(distinct, options);
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
