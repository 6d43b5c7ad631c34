#include "app/solution/shader_fit.h"

#include <cmath>
#include <vector>

#include "app/solution/document_albedo.h"
#include "app/solution/pair_evaluation.h"
#include "app/solution/solved_document.h"
#include "core/conventions.h"

namespace skinlayer {

BrdfFitTarget principled_fit_target(const MaterialDocument& document, const ParallelFor& parallel_for) {
  BrdfFitTarget target;
  target.pairs = fit_pairs();
  std::vector<double> theta_i, theta_o, phi;
  for (const DirectionPair& pair : target.pairs) {
    theta_i.push_back(radians_to_degrees(std::acos(pair.omega_i.z())));
    theta_o.push_back(radians_to_degrees(std::acos(pair.omega_o.z())));
    phi.push_back(radians_to_degrees(std::atan2(pair.omega_o.y(), pair.omega_o.x())));  // the light is at azimuth 0
  }
  const SolvedDocument solved = solve_document(document, SubsurfaceModel::Stam, parallel_for);
  const std::size_t n = target.pairs.size(), width = static_cast<std::size_t>(value_channels(solved));
  std::vector<double> surface(n), subsurface(n * width), brdf(n * width), btdf(n * width);
  evaluate_pairs(solved, theta_i, theta_o, phi, {surface, subsurface, brdf, btdf}, parallel_for);
  for (std::size_t k = 0; k < n; ++k) {
    Rgb value;
    for (int c = 0; c < 3; ++c) value(c) = brdf[k * width + (width == 1 ? 0 : static_cast<std::size_t>(c))];
    target.brdf_cosine.push_back(value * target.pairs[k].omega_i.z());
  }
  for (int degrees = 0; degrees <= 80; degrees += 20) target.albedo_angles.push_back(degrees_to_radians(degrees));
  const std::vector<std::vector<DirectionalAlbedo>> albedo =
      document_albedo(document, target.albedo_angles, parallel_for);
  for (std::size_t a = 0; a < target.albedo_angles.size(); ++a) {
    Rgb value;
    for (int c = 0; c < 3; ++c)
      value(c) = albedo[albedo.size() == 1 ? 0 : static_cast<std::size_t>(c)][a].reflectance();
    target.albedo.push_back(value);
  }
  return target;
}

PrincipledFit fit_principled(const MaterialDocument& document, const ParallelFor& parallel_for) {
  return fit_principled(principled_fit_target(document, parallel_for));
}

}  // namespace skinlayer
