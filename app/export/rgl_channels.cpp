#include "app/export/rgl_channels.h"

#include <memory>
#include <stdexcept>
#include <vector>

#include "app/material/color_channels.h"
#include "core/color/luminance.h"
#include "core/color/rgb_uplift.h"
#include "core/color/spectral_color.h"
#include "core/models/subsurface_model.h"
#include "core/solve/batch_solve.h"

namespace skinlayer {
namespace {

// Per wavelength, its share of Y: the luminance row applied to the wavelengths' linear-sRGB weights.
std::vector<double> luminance_weights(std::span<const double> wavelengths) {
  const Eigen::Matrix<double, 3, Eigen::Dynamic> to_rgb = linear_srgb_weights(wavelengths);
  std::vector<double> weights;
  for (Eigen::Index k = 0; k < to_rgb.cols(); ++k) {
    weights.push_back(luminance(to_rgb(0, k), to_rgb(1, k), to_rgb(2, k)));
  }
  return weights;
}

}  // namespace

RglChannels rgl_rgb_channels(const ColorTables& tables) {
  RglChannels channels;
  channels.luminance_weights.assign(kRec709Luminance.begin(), kRec709Luminance.end());
  channels.top_sigma = tables.material.layer.sigma;
  channels.brdf = [&tables](double theta_i, double theta_o, double phi, std::span<double> values) {
    for (int c = 0; c < 3; ++c) values[c] = brdf_total(tables, c, theta_i, theta_o, phi);
  };
  return channels;
}

RglChannels rgl_uplifted_channels(const ColorTables& tables) {
  RglChannels channels;
  channels.wavelengths.assign(kUpliftWavelengths.begin(), kUpliftWavelengths.end());
  channels.luminance_weights = luminance_weights(channels.wavelengths);
  channels.top_sigma = tables.material.layer.sigma;
  const auto uplift = std::make_shared<const RgbUplift>(channels.wavelengths);
  channels.brdf = [&tables, uplift](double theta_i, double theta_o, double phi, std::span<double> values) {
    std::array<double, 3> rgb{};
    for (int c = 0; c < 3; ++c) rgb[c] = std::max(0.0, brdf_total(tables, c, theta_i, theta_o, phi));
    uplift->values(uplift->fit(rgb), values);
  };
  return channels;
}

RglChannels rgl_skin_channels(const ColorMaterial& material, const SolveOptions& options) {
  if (!material.skin) throw std::invalid_argument("rgl_skin_channels: not a skin");
  const ColorChannels grid = color_channels(material_document(material));
  auto tables = std::make_shared<std::vector<LayerTables>>(grid.materials.size());
  for_each_with_warm_cache(grid.materials.size(), options, [&](std::size_t k, const SolveOptions& one) {
    (*tables)[k] = material.model == SubsurfaceModel::Stam ? solve(grid.materials[k], one)
                                                           : solve_model(grid.materials[k], material.model, one);
  });
  RglChannels channels;
  channels.wavelengths = grid.wavelengths_nm;
  channels.luminance_weights = luminance_weights(channels.wavelengths);
  channels.top_sigma = material.layer.sigma;
  const Material top = grid.materials.front();
  channels.brdf = [tables, top](double theta_i, double theta_o, double phi, std::span<double> values) {
    const double surface = brdf_surface(top, theta_i, theta_o, phi);
    for (std::size_t k = 0; k < tables->size(); ++k)
      values[k] = surface + (*tables)[k].brdf_subsurface(theta_i, theta_o, phi);
  };
  return channels;
}

}  // namespace skinlayer
