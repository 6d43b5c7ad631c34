#include "app/solution/solved_document.h"

#include <Eigen/Core>

#include "core/solve/batch_solve.h"
#include "core/solve/solve_cache.h"
#include "core/solver.h"

namespace skinlayer {

SolvedDocument solve_document(const MaterialDocument& document, SubsurfaceModel model, const ParallelFor& parallel_for,
                              const std::function<bool()>& cancelled) {
  SolvedDocument solved;
  solved.grey = document.grey();
  solved.model = model;
  solved.channels = color_channels(document);
  SolveCache cache;
  SolveOptions options;
  options.parallel_for = parallel_for;
  options.cancelled = cancelled;
  if (solved.grey) {
    solved.tables.push_back(solve_model(document.layer, model, options));
    return solved;
  }
  options.cache = &cache;  // the interface operators are built once for every channel
  if (model == SubsurfaceModel::Stam) {
    solved.tables = solve_batch(solved.channels.materials, options);  // whole solves side by side
    return solved;
  }
  for (const Material& material : solved.channels.materials)
    solved.tables.push_back(solve_model(material, model, options));
  return solved;
}

BsdfPoint evaluate(const SolvedDocument& solved, double theta_i, double theta_o, double phi) {
  BsdfPoint point;
  point.surface = brdf_surface(solved.channels.materials.front(), theta_i, theta_o, phi);
  if (solved.grey) {
    const LayerTables& tables = solved.tables.front();
    const LayerTables::Values values = tables.values(theta_i, theta_o, phi);
    point.subsurface.fill(values.brdf_subsurface);
    point.btdf.fill(values.btdf);
    return point;
  }
  const auto count = static_cast<Eigen::Index>(solved.tables.size());
  Eigen::VectorXd subsurface_k(count), btdf_k(count);
  for (Eigen::Index k = 0; k < count; ++k) {
    const LayerTables& tables = solved.tables[static_cast<std::size_t>(k)];
    const LayerTables::Values values = tables.values(theta_i, theta_o, phi);
    subsurface_k(k) = values.brdf_subsurface;
    btdf_k(k) = values.btdf;
  }
  const Eigen::Vector3d subsurface = solved.channels.to_rgb * subsurface_k, btdf = solved.channels.to_rgb * btdf_k;
  for (int c = 0; c < 3; ++c) {
    point.subsurface[c] = subsurface[c];
    point.btdf[c] = btdf[c];
  }
  return point;
}

}  // namespace skinlayer
