#include "app/material/color_channels.h"

#include "core/color/spectral_color.h"
#include "core/skin/skin_optics.h"

namespace skinlayer {

std::vector<double> skin_color_wavelengths() { return wavelength_grid(400.0, 700.0, 10.0); }

ColorChannels color_channels(const MaterialDocument& document) {
  ColorChannels channels;
  if (document.skin) {
    channels.wavelengths_nm = skin_color_wavelengths();
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

}  // namespace skinlayer
