#include "core/skin/skin_spectrum.h"

#include "core/solve/solve_cache.h"

namespace skinlayer {

std::vector<std::vector<DirectionalAlbedo>> skin_directional_albedo(const SkinParameters& skin,
                                                                    const Material& interfaces,
                                                                    std::span<const double> wavelengths_nm,
                                                                    std::span<const double> theta_i,
                                                                    const SolveOptions& options) {
  validate(skin);
  SolveCache own_cache;
  SolveOptions with_cache = options;
  if (with_cache.cache == nullptr) with_cache.cache = &own_cache;
  std::vector<std::vector<DirectionalAlbedo>> rows;
  rows.reserve(wavelengths_nm.size());
  for (const double wavelength : wavelengths_nm) {
    rows.push_back(directional_albedo(skin_material(skin, wavelength, interfaces), theta_i, with_cache));
  }
  return rows;
}

}  // namespace skinlayer
