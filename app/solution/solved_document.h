// A material document solved once and evaluated at any direction pair: what `skinlayer eval` writes and what the
// Python module's Solution.eval returns, through the same code, so the two agree to the last bit.
//
// A grey document is one solve. A colour document (RGB, or a skin's spectrum) is one solve per entry of
// color_channels(document), and each channel's value is the channels' weighted sum (app/material/color_channels.h).
// Angles are radians in core/conventions.h's graphics convention; every value is a BSDF in 1/sr, not cosine-weighted.
#pragma once

#include <array>
#include <functional>
#include <span>
#include <vector>

#include "app/material/color_channels.h"
#include "app/material/material_document.h"
#include "core/models/subsurface_model.h"
#include "core/parallel_for.h"
#include "core/series/layer_tables.h"
#include "core/unscattered/tabulated_two_interface.h"

namespace skinlayer {

struct SolvedDocument {
  bool grey = true;                 // one solve: every channel is that solve's value
  ColorChannels channels;           // the solves and their weights into linear sRGB
  std::vector<LayerTables> tables;  // one per channels.materials entry
  SubsurfaceModel model = SubsurfaceModel::Stam;
};

// Solves the document with `model` (the surface term is the same for every model). The colour channels' solves go
// side by side through one interface cache (solve_batch) for the layer model. A skin under a comparison model is the
// RGB layer that stands for it (app/solution/skin_comparison.h). Throws ParameterError for a material
// out of range and SolveCancelled when `cancelled` returns true between the solver's stages.
SolvedDocument solve_document(const MaterialDocument& document, SubsurfaceModel model, const ParallelFor& parallel_for,
                              const std::function<bool()>& cancelled = {});

// The BSDF at one direction pair, per channel (red, green, blue; for a grey document the three are equal):
// brdf = surface + subsurface; btdf is the light into the medium below without the unscattered beam.
struct BsdfPoint {
  double surface = 0.0;  // the top interface's reflection: no albedo in it, the same in every channel
  std::array<double, 3> subsurface{};
  std::array<double, 3> btdf{};
};
// A channel whose unscattered light is among `lobes` takes its BTDF from that table (within 0.5% of the lobe's peak,
// core/unscattered/tabulated_two_interface.h) instead of the pointwise quadrature (~100-200 us a pair).
BsdfPoint evaluate(const SolvedDocument& solved, double theta_i, double theta_o, double phi,
                   std::span<const TabulatedTwoInterfaceBtdf> lobes = {});

// The tables of the document's distinct two-interface unscattered lights that can be tabulated (one for a grey
// document or a colour sharing its interfaces and depth; none for other paths or sigma < 0.15), ~0.1 s each on
// 2 cores: worth it for thousands of pairs (evaluate_pairs, app/solution/pair_evaluation.h).
std::vector<TabulatedTwoInterfaceBtdf> tabulate_unscattered(const SolvedDocument& solved,
                                                            const ParallelFor& parallel_for);

}  // namespace skinlayer
