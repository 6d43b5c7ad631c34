#include "app/solution/document_albedo.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "app/material/color_channels.h"
#include "core/solve/batch_solve.h"

namespace skinlayer {
namespace {

void require_rows(const std::vector<DirectionalAlbedo>& rows, std::size_t angles) {
  if (rows.size() != angles) {
    throw std::runtime_error("the solver returned " + std::to_string(rows.size()) + " albedo rows for " +
                             std::to_string(angles) + " angles");
  }
}

}  // namespace

std::vector<std::vector<DirectionalAlbedo>> document_albedo(const MaterialDocument& document,
                                                            std::span<const double> thetas_radians,
                                                            const ParallelFor& parallel_for,
                                                            const std::function<bool()>& cancelled) {
  SolveOptions options;
  options.parallel_for = parallel_for;
  options.cancelled = cancelled;
  return document_albedo(document, thetas_radians, options);
}

std::vector<std::vector<DirectionalAlbedo>> document_albedo(const MaterialDocument& document,
                                                            std::span<const double> thetas_radians,
                                                            const SolveOptions& options) {
  if (document.grey()) {
    std::vector<std::vector<DirectionalAlbedo>> grey = {directional_albedo(document.layer, thetas_radians, options)};
    require_rows(grey.front(), thetas_radians.size());
    return grey;
  }
  const ColorChannels channels = color_channels(document);
  std::vector<std::vector<DirectionalAlbedo>> solved;
  if (document.skin) {  // one stack per wavelength, side by side with warm caches of the interfaces
    solved.resize(channels.materials.size());
    for_each_with_warm_cache(channels.materials.size(), options, [&](std::size_t k, const SolveOptions& one) {
      solved[k] = directional_albedo(channels.materials[k], thetas_radians, one);
    });
  } else {  // the distinct channels in one solve, sharing every albedo-independent step
    solved = directional_albedo(channels.materials, thetas_radians, options);
  }
  for (const std::vector<DirectionalAlbedo>& rows : solved) require_rows(rows, thetas_radians.size());
  std::vector<std::vector<DirectionalAlbedo>> rgb(3);
  std::vector<DirectionalAlbedo> at_angle(solved.size());
  for (std::size_t a = 0; a < thetas_radians.size(); ++a) {
    for (std::size_t k = 0; k < solved.size(); ++k) at_angle[k] = solved[k][a];
    for (int c = 0; c < 3; ++c)
      rgb[static_cast<std::size_t>(c)].push_back(mixed_albedo(at_angle, channels.to_rgb.row(c)));
  }
  return rgb;
}

std::vector<Eigen::Array3d> document_reflectance_rgb(const MaterialDocument& document,
                                                     std::span<const double> thetas_radians,
                                                     const ParallelFor& parallel_for) {
  const std::vector<std::vector<DirectionalAlbedo>> channels = document_albedo(document, thetas_radians, parallel_for);
  std::vector<Eigen::Array3d> rgb(thetas_radians.size());
  for (std::size_t a = 0; a < rgb.size(); ++a) {
    for (std::size_t c = 0; c < 3; ++c) {
      rgb[a](static_cast<Eigen::Index>(c)) = channels[std::min(c, channels.size() - 1)][a].reflectance();
    }
  }
  return rgb;
}

}  // namespace skinlayer
