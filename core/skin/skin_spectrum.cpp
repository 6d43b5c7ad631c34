#include "core/skin/skin_spectrum.h"

#include "core/solve/batch_solve.h"

namespace skinlayer {

std::vector<std::vector<DirectionalAlbedo>> skin_directional_albedo(const SkinParameters& skin,
                                                                    const Material& interfaces,
                                                                    std::span<const double> wavelengths_nm,
                                                                    std::span<const double> theta_i,
                                                                    const SolveOptions& options) {
  validate(skin);
  std::vector<std::vector<DirectionalAlbedo>> rows(wavelengths_nm.size());
  for_each_with_warm_cache(wavelengths_nm.size(), options, [&](std::size_t k, const SolveOptions& one) {
    rows[k] = directional_albedo(skin_material(skin, wavelengths_nm[k], interfaces), theta_i, one);
  });
  return rows;
}

}  // namespace skinlayer
