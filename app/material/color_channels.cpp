#include "app/material/color_channels.h"

#include <algorithm>

#include "core/color/spectral_color.h"
#include "core/skin/skin_optics.h"

namespace skinlayer {

std::vector<double> skin_color_wavelengths() { return wavelength_grid(400.0, 700.0, 10.0); }

std::vector<double> skin_preview_wavelengths() { return wavelength_grid(400.0, 700.0, 50.0); }

ColorChannels color_channels(const MaterialDocument& document, bool preview) {
  ColorChannels channels;
  if (document.skin) {
    channels.wavelengths_nm = preview ? skin_preview_wavelengths() : skin_color_wavelengths();
    for (const double wavelength : channels.wavelengths_nm) {
      channels.materials.push_back(skin_material(*document.skin, wavelength, document.layer));
    }
    channels.to_rgb = linear_srgb_weights(channels.wavelengths_nm);
    return channels;
  }
  const DistinctChannels distinct = distinct_channels(document);
  channels.materials = distinct.materials;
  channels.to_rgb =
      Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, static_cast<Eigen::Index>(distinct.materials.size()));
  for (int c = 0; c < 3; ++c)
    channels.to_rgb(c, static_cast<Eigen::Index>(distinct.index[static_cast<std::size_t>(c)])) = 1.0;
  return channels;
}

DirectionalAlbedo mixed_albedo(std::span<const DirectionalAlbedo> per_solve, const Eigen::RowVectorXd& weights) {
  DirectionalAlbedo row = per_solve.front();
  row.reflectance_subsurface = row.transmittance = row.absorptance = row.interface_loss = 0.0;
  std::fill(row.layer_absorptance.begin(), row.layer_absorptance.end(), 0.0);
  for (std::size_t k = 0; k < per_solve.size(); ++k) {
    const double w = weights(static_cast<Eigen::Index>(k));
    const DirectionalAlbedo& one = per_solve[k];
    row.reflectance_subsurface += w * one.reflectance_subsurface;
    row.transmittance += w * one.transmittance;
    row.absorptance += w * one.absorptance;
    row.interface_loss += w * one.interface_loss;
    for (std::size_t i = 0; i < row.layer_absorptance.size(); ++i)
      row.layer_absorptance[i] += w * one.layer_absorptance[i];
  }
  return row;
}

}  // namespace skinlayer
