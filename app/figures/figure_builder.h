// Builds one figure of the set: samples its lobes (every 1 degree in the plane of incidence), writes NAME.csv with
// the data behind the picture and NAME.png. Layers are solved once per distinct material and model (a cache shared
// across figures).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "app/figures/figure_set.h"
#include "app/figures/font.h"
#include "core/series/layer_tables.h"

namespace skinlayer::figures {

class SolveCache {
 public:
  const LayerTables& tables(const LayerParams& params, SubsurfaceModel model);

 private:
  struct Entry {
    Material material;
    SubsurfaceModel model;
    LayerTables tables;
  };
  std::vector<Entry> solved_;  // a few dozen at most: found by comparing the materials
};

// Writes dir/NAME.csv and dir/NAME.png (a `size` x `size` polar plot, or the sphere strip for ModelSpheres).
// The CSV header: curve,parameter,value,theta_i,theta_o,phi,side,quantity,f[,plotted],model,sigma,eta,T,albedo,g —
// angles in degrees as skinlayer eval reads them, side R or T, f in 1/sr before any rescaling (plotted: after), and
// the material and model so `skinlayer eval --model M --sigma .. --eta .. --T .. --albedo .. --g ..` reproduces f in
// eval's column named by quantity (brdf_subsurface, btdf or brdf_surface); quantity interface_btdf (the surface
// figures' T side: core's microfacet_btdf into the layer) has no eval column. A stack's rows also fill the last
// column, layers: its --layer values top to bottom, separated by spaces, with ';' for ',' inside each (T, albedo
// and g then repeat the first layer's); it is empty for one layer.
// Returns the PNG's size. Throws std::runtime_error if a file cannot be written.
struct FigureSize {
  int width = 0;
  int height = 0;
};
// How a figure was drawn, for its PNG's metadata: the command, the figure, the parameter it varies and its values, and
// the first curve's incident angle (degrees).
nlohmann::ordered_json figure_settings(const FigureSpec& spec);

FigureSize build_figure(const FigureSpec& spec, const std::filesystem::path& dir, const Font& font, SolveCache& cache,
                  int size);

}  // namespace skinlayer::figures
