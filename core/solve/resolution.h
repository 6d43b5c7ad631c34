// The resolution policy: the discretization a solve uses (ordinates N, the Fourier-mode cap, the table size K, the
// interface and phase-function projections), chosen from the material, its ordinates override and the options
// (a given table size or mode cap, the preview's caps). Each rule's reason and the measurements behind it are
// written where it is implemented (resolution.cpp); docs/model.md §4 summarizes them.
#pragma once

#include "core/material.h"
#include "core/solve/solve_options.h"

namespace skinlayer {

// The discretization a solve uses, chosen from the material (and its ordinates override).
struct Resolution {
  int ordinates;           // N, discrete ordinates per hemisphere
  int max_modes;           // cap on Fourier modes
  int table_size;          // K, polar grid size of the tables
  int interface_modes;     // Fourier modes the interface operators are projected onto: max_modes rounded up to a
                           // multiple of 16, so that a change of g or of the mode cap keeps them (SolveCache)
  int interface_azimuths;  // azimuth samples on [0, pi] for projecting interface BSDFs
  int phase_azimuths;      // azimuth samples on [0, pi] for projecting the phase function
};
Resolution choose_resolution(const Material& material, const SolveOptions& options = {});

// True when SolveOptions::preview would solve this material at a coarser resolution than the full solve does.
bool preview_is_coarser(const Material& material);

}  // namespace skinlayer
