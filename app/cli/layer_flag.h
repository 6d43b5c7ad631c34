// One layer of a stack on the command line (issue 12's contract): --layer KEY=VALUE[,KEY=VALUE...], repeated top
// to bottom. Keys: T or tau (one of them, required), albedo (a number; r:g:b where the command takes RGB), g, and
// for every layer but the first, sigma and eta of a rough interface above it (both or neither; eta = n_this /
// n_above, 1 = no interface), and mu_t, the layer's extinction coefficient in 1/mm (optional; it gives the layer a
// thickness tau / mu_t mm). An omitted albedo or g takes its default from core's parameter table.
#pragma once

#include <optional>
#include <string_view>

#include "app/material/material_document.h"
#include "app/material/material_flag_text.h"
#include "core/material.h"

namespace skinlayer::cli {

struct LayerSpec {
  double tau = 0.0;
  AlbedoRgb albedo{};
  double g = 0.0;
  std::optional<LayerInterface> interface;
  std::optional<double> extinction;  // mu_t, 1/mm
};

// place: the layer's 1-based place in the order, named by every error ("layer 2: g = 1.5 is out of range; valid
// range is [-0.95, 0.95] (Henyey-Greenstein asymmetry)"). Throws skinlayer::ParameterError for a value out of
// range, UsageError for anything else malformed.
LayerSpec parse_layer_spec(std::string_view text, int place, bool rgb_albedo);

}  // namespace skinlayer::cli
