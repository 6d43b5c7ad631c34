#include "app/material/color_match.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/color/ciede2000.h"
#include "core/fit/albedo_color_match.h"
#include "core/fit/skin_fit.h"

namespace skinlayer {

DocumentColorMatch match_document_color(MaterialDocument document, const Eigen::Vector3d& target,
                                        const ParallelFor& parallel_for) {
  DocumentColorMatch result;
  if (document.skin) {
    const SkinColorMatch match = match_skin_color(target, document.layer, *document.skin, parallel_for);
    document.skin = match.skin;
    result.reached = match.color;
  } else {
    std::array<Material, 3> channels;
    for (int c = 0; c < 3; ++c) channels[static_cast<std::size_t>(c)] = document.channel(c);
    const AlbedoColorMatch match = match_top_albedo(channels, {target(0), target(1), target(2)});
    document.set_layer_albedo(0, match.albedo);
    result.reached = Eigen::Vector3d(match.reflectance[0], match.reflectance[1], match.reflectance[2]);
  }
  result.reachable = true;
  for (int c = 0; c < 3; ++c) {
    result.reachable = result.reachable && std::abs(result.reached(c) - target(c)) <= std::max(5e-3 * target(c), 1e-4);
  }
  result.delta_e = ciede2000(linear_srgb_to_lab(target), linear_srgb_to_lab(result.reached));
  result.document = std::move(document);
  return result;
}

}  // namespace skinlayer
