#include "app/solution/solved_document.h"

#include <Eigen/Core>
#include <algorithm>

#include "app/solution/material_solve.h"
#include "app/solution/skin_comparison.h"
#include "core/solve/batch_solve.h"
#include "core/solve/solve_cache.h"
#include "core/solver.h"

namespace skinlayer {

SolvedDocument solve_document(const MaterialDocument& document, SubsurfaceModel model, const ParallelFor& parallel_for,
                              const std::function<bool()>& cancelled) {
  if (document.skin && model != SubsurfaceModel::Stam) {
    // The comparison models describe one layer: for a skin, the RGB layer that stands for it (skin_comparison.h).
    SolveOptions options;
    options.parallel_for = parallel_for;
    options.cancelled = cancelled;
    const ColorMaterial layer = skin_comparison_layer(color_material(document), options).layer;
    return solve_document(material_document(layer), model, parallel_for, cancelled);
  }
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

std::vector<TabulatedTwoInterfaceBtdf> tabulate_unscattered(const SolvedDocument& solved,
                                                            const ParallelFor& parallel_for) {
  std::vector<TabulatedTwoInterfaceBtdf> lobes;
  for (const LayerTables& tables : solved.tables) {
    const UnscatteredLight& light = tables.unscattered();
    if (!TabulatedTwoInterfaceBtdf::can_tabulate(light)) continue;
    if (std::ranges::any_of(lobes, [&](const auto& lobe) { return lobe.light() == light; })) continue;
    lobes.emplace_back(light, parallel_for);
  }
  return lobes;
}

namespace {

// The unscattered BTDF of `light` at the pair: from its table in `lobes` if there is one, else pointwise.
double unscattered_btdf_at(const UnscatteredLight& light, std::span<const TabulatedTwoInterfaceBtdf> lobes,
                           double theta_i, double theta_o, double phi) {
  for (const TabulatedTwoInterfaceBtdf& lobe : lobes) {
    if (lobe.light() == light) return lobe.btdf(theta_i, theta_o, phi);
  }
  return light.btdf(theta_i, theta_o, phi);
}

}  // namespace

BsdfPoint evaluate(const SolvedDocument& solved, double theta_i, double theta_o, double phi,
                   std::span<const TabulatedTwoInterfaceBtdf> lobes) {
  BsdfPoint point;
  point.surface = brdf_surface(solved.channels.materials.front(), theta_i, theta_o, phi);
  // A grey document is one table with weight 1 in every channel. A colour's tables usually share one grid size and
  // one unscattered light (the interfaces and the depth are the same, only the albedo differs): the stencil and the
  // unscattered values are found again only where they change.
  LayerTables::Stencil taps = LayerTables::stencil(theta_i, theta_o, solved.tables.front().grid_size());
  const UnscatteredLight* unscattered = nullptr;
  double unscattered_brdf = 0.0, unscattered_btdf = 0.0;
  for (std::size_t k = 0; k < solved.tables.size(); ++k) {
    const LayerTables& tables = solved.tables[k];
    if (tables.grid_size() != taps.grid_size) taps = LayerTables::stencil(theta_i, theta_o, tables.grid_size());
    if (unscattered == nullptr || !(tables.unscattered() == *unscattered)) {
      unscattered = &tables.unscattered();
      unscattered_brdf = unscattered->brdf(theta_i, theta_o, phi);
      unscattered_btdf = unscattered_btdf_at(*unscattered, lobes, theta_i, theta_o, phi);
    }
    const LayerTables::ScatteredValues scattered = tables.scattered(taps, phi);
    const double subsurface = scattered.reflection + unscattered_brdf;
    const double btdf = scattered.transmission + unscattered_btdf;
    for (int c = 0; c < 3; ++c) {
      const double weight = solved.channels.to_rgb(c, static_cast<Eigen::Index>(k));
      point.subsurface[c] += weight * subsurface;
      point.btdf[c] += weight * btdf;
    }
  }
  return point;
}

}  // namespace skinlayer
