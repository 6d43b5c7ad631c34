// The previewer's edits of a stack's list of layers (the layers panel): add, remove and reorder, as pure functions on
// the material the previewer owns, so that every result is a valid stack and the panel (params_ui) stays a view.
//
// A layer carries the interface above it when it moves; the first layer never has one (the top interface is
// above it), so a layer moved to the top drops its own. Only the last layer may be semi-infinite: a move that
// would bury a semi-infinite layer is refused (can_move), and a layer added under a semi-infinite one takes its
// place at the bottom while the old last layer becomes finite.
#pragma once

#include <cstddef>
#include <vector>

#include "app/material/material_document.h"
#include "app/solution/material_solve.h"

namespace skinlayer {

struct EditableLayer {
  StackedLayer layer;  // its interface above (ignored for the first) and depth, albedo (albedo[0]) and g
  AlbedoRgb albedo{1.0, 1.0, 1.0};
};

std::vector<EditableLayer> editable_layers(const ColorMaterial& material);
void set_layers(ColorMaterial& material, std::vector<EditableLayer> layers);

// The depth given to a layer that stops being the last one while semi-infinite: T 0.5.
inline constexpr double kUnburiedDepth = 0.6931471805599453;

// Appends a copy of the last layer below it (finite: a semi-infinite last layer keeps its place at the bottom
// and the copy above it gets kUnburiedDepth). The new layer has no interface above it. The model becomes the
// layer model (the comparison models describe one layer).
void add_layer(ColorMaterial& material);
// Removes layer i (0-based) unless it is the only one.
void remove_layer(ColorMaterial& material, std::size_t i);
// Swaps layer i with its neighbour (offset -1: up, +1: down) when can_move says so.
bool can_move(const ColorMaterial& material, std::size_t i, int offset);
void move_layer(ColorMaterial& material, std::size_t i, int offset);

}  // namespace skinlayer
