#include "app/export/color_export.h"

#include <algorithm>
#include <cmath>

namespace skinlayer {

std::string merl_file(const ColorTables& tables, const std::function<void(int, int)>& progress,
                      const std::function<void(int, const std::function<void(int)>&)>& parallel_for) {
  const bool grey = material_document(tables.material).grey();
  const RgbBrdf brdf = [&](const Vec3& incident, const Vec3& outgoing) {
    // core/conventions.h's angles: theta from the normal, phi the outgoing azimuth minus the incident one.
    const double theta_i = std::acos(std::min(1.0, incident.z()));
    const double theta_o = std::acos(std::min(1.0, outgoing.z()));
    const double phi = std::atan2(outgoing.y(), outgoing.x()) - std::atan2(incident.y(), incident.x());
    const double red = brdf_total(tables, 0, theta_i, theta_o, phi);
    if (grey) return std::array<double, 3>{red, red, red};
    return std::array<double, 3>{red, brdf_total(tables, 1, theta_i, theta_o, phi),
                                 brdf_total(tables, 2, theta_i, theta_o, phi)};
  };
  return encode_merl(brdf, progress, parallel_for);
}

std::string scatfun_file(const ColorTables& tables, int nodes, const SolveOptions& options,
                         const std::function<void(int, int)>& progress) {
  std::optional<ColorTables> below;
  if (const std::optional<ColorMaterial> flipped = upside_down(tables.material)) {
    below = solve_color(*flipped, 0.0, options);
  }
  return encode_scatfun(scatfun_table(tables, below ? &*below : nullptr, nodes, progress, options.parallel_for));
}

}  // namespace skinlayer
