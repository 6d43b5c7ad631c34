#include "app/solution/skin_comparison.h"

#include <limits>
#include <stdexcept>
#include <vector>

#include "app/solution/document_albedo.h"
#include "core/fit/albedo_color_match.h"
#include "core/skin/skin_optics.h"
#include "core/solver.h"

namespace skinlayer {

SkinComparisonLayer skin_comparison_layer(const ColorMaterial& skin, const SolveOptions& options) {
  if (!skin.skin) throw std::invalid_argument("skin_comparison_layer: the material is no skin");
  // The skin's reflectance at normal incidence per channel (its spectrum mixed into linear sRGB).
  const double normal[1] = {0.0};
  const std::vector<std::vector<DirectionalAlbedo>> rgb = document_albedo(material_document(skin), normal, options);
  SkinComparisonLayer result;
  for (std::size_t c = 0; c < 3; ++c) result.reflectance[c] = rgb[c].front().reflectance();

  Material layer;
  layer.sigma = skin.layer.sigma;
  layer.eta = skin.layer.eta;
  layer.ordinates = skin.layer.ordinates;
  layer.tau = std::numeric_limits<double>::infinity();  // semi-infinite, as the skin's dermis
  layer.g = kSkinAnisotropy;
  layer.bottom.kind = BottomKind::Matched;  // never reached under a semi-infinite layer
  const std::array<Material, 3> channels = {layer, layer, layer};
  const AlbedoColorMatch match = match_top_albedo(channels, result.reflectance, options);
  layer.albedo = match.albedo[0];
  result.layer.layer = layer;
  result.layer.albedo_rgb = match.albedo;
  result.layer.model = SubsurfaceModel::Stam;
  return result;
}

}  // namespace skinlayer
