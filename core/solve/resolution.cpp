#include "core/solve/resolution.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/interfaces/microfacet.h"

namespace skinlayer {
namespace {

constexpr int kDefaultTableSize = 48;

int ceil_to_int(double x) { return static_cast<int>(std::ceil(x)); }

// How near-matched an interface is: 0 at eta >= 1.2 (or <= 1/1.2), rising linearly to 1 at 1.1 and below.
double near_matched(const RoughDielectric& interface) {
  const double n = std::max(interface.eta, 1.0 / interface.eta);
  return std::clamp((1.2 - n) / 0.1, 0.0, 1.0);
}

// The refracted lobe of a rough interface, seen from inside, is about w = sigma (1 - 1/eta) radians wide (a facet
// tilt of sigma turns the refracted ray by that much less than it turns the normal). Where the lobe falls between
// the ordinates the exit sums ripple across exit angles. N >= c / w with c = 1.75 held every eta >= 1.2 of the
// pointwise sweep (docs/accuracy.md) within 0.7%; a near-matched interface transmits nearly everything through that
// lobe and its critical angle lies near grazing, so the ripple is not diluted: at eta 1.05, sigma 1 against N 192
// (points, not bins) N w = 1.9 leaves 18%, 4.6 1.6% and 6.1 1.2% (0.5% with the finer tables of
// lobe_table_size). So c rises linearly from 1.75 at eta 1.2 to 6 at eta 1.1 and below. N is at most 128 (0.15-2 s
// per solve on the 2-core VM), so near-matched lobes narrower than 6/128 = 0.047 rad (eta 1.05 below sigma 1, eta
// 1.1 below sigma 0.52) stay under-resolved: 1-5% pointwise at sigma 0.05-0.1, eta 1.05, where N 192 is no
// converged reference either (N w = 0.9-1.8).
int refracted_lobe_ordinates(const LayerGeometry& geometry) {
  const auto need = [](const RoughDielectric& interface) {
    const double c = 1.75 + (6.0 - 1.75) * near_matched(interface);
    return ceil_to_int(std::min(c / refracted_lobe_width(interface), 128.0));
  };
  int result = 0;
  if (!geometry.top_open) result = need(geometry.top);
  if (geometry.base == LayerBase::Rough) result = std::max(result, need(geometry.bottom));
  return result;
}

// The tables' polar grid (LayerTables::grid_angle) is spaced h = (pi/2)^2 / (K - 1) radians at the normal and finer
// towards grazing; Catmull-Rom between its nodes must follow the sharpest lobe the tables hold. The unscattered
// transmission is exact outside them (core/unscattered/unscattered_light.h); three sharp features stay in them:
// - the unscattered light's reflection off a rough bottom (Beckmann sigma3, seen through the top about
//   s = sigma3 eta wide), where it is not buried under scattered light: T^2 > Omega (1 - T) / 4;
// - single forward scattering (Henyey-Greenstein, half width 0.77 (1 - g) / sqrt(g) radians) of light that crossed
//   the top's refracted lobe, widened by the exit's lobe, where the layer (a stack: all of it) transmits (T >= 0.05);
// - a near-matched interface's critical angle lies near grazing, where its refracted lobe (w) is stretched outside
//   and cuts the scattered light sharply.
// Measured pointwise against a 95-node grid (docs/accuracy.md): a bottom bounce errs 8.8% at h = 0.75 s (sigma3
// 0.05, T 0.5, Omega 0) and 0.6% at 0.37 s, and 1.2% at 0.27 s where the bottom's critical angle cuts the lobe
// (sigma3 0.1, eta3 1.2): h <= 0.22 s. A forward lobe of width w errs 2.6% at h = 0.64 w and 0.57% at 0.43 w; the
// DISORT stacks (tests/reference/disort_multilayer_intensities.csv, g 0.8 under T 0.22 and 0.1) err 0.17-0.22%
// straight through at 0.4 w (K 48) and 1.4e-4 at 0.25 w (K 64): h <= 0.25 w where T >= 0.05. At eta 1.05, sigma 1 (N
// 128) h = 1.1 w errs 1.2%, 0.73 w 0.5%: h <= 0.8 w, relaxed as eta leaves 1.1 (near_matched). K is a multiple of 8 in
// [48, 96]; 48 (3 degrees at the normal) where none binds, the default material included.
int lobe_table_size(const Material& material, const LayerGeometry& geometry) {
  constexpr double kQuarterPiSquared = 0.25 * kPi * kPi;
  double spacing = kQuarterPiSquared / (kDefaultTableSize - 1);
  const double transparency = material.transparency();
  if (geometry.base == LayerBase::Rough &&
      transparency * transparency > 0.25 * material.albedo * (1.0 - transparency)) {
    const double top_eta = geometry.top_open ? 1.0 : geometry.top.eta;
    spacing = std::min(spacing, 0.22 * geometry.bottom.sigma * top_eta);
  }
  if (geometry.base != LayerBase::Lambert && transparency >= 0.05 && material.g > 0.0) {
    const double forward = 0.77 * (1.0 - material.g) / std::sqrt(material.g);
    const double entry = geometry.top_open ? 0.0 : refracted_lobe_width(geometry.top);
    const double exit = geometry.base == LayerBase::Rough ? refracted_lobe_width(geometry.bottom) : 0.0;
    spacing = std::min(spacing, 0.25 * std::sqrt(forward * forward + entry * entry + exit * exit));
  }
  for (const RoughDielectric* interface :
       {geometry.top_open ? nullptr : &geometry.top, geometry.base == LayerBase::Rough ? &geometry.bottom : nullptr}) {
    const double nearness = interface ? near_matched(*interface) : 0.0;
    if (nearness > 0.0) spacing = std::min(spacing, 0.8 * refracted_lobe_width(*interface) / nearness);
  }
  const int nodes = ceil_to_int(1.0 + kQuarterPiSquared / spacing - 1e-9);
  return std::clamp((nodes + 7) / 8 * 8, kDefaultTableSize, 96);
}

// Single layers whose resolutions together cover a stack's: each layer's scattering (its albedo and g) over the
// whole stack's depth, between the stack's top and bottom; and each internal interface in the top's place (as
// seen from its denser side, the refracted lobe being the same width either way).
std::vector<Material> resolution_envelopes(const Material& material) {
  Material base = material;
  base.below.clear();
  base.tau = material.total_tau();
  if (base.bottom.kind == BottomKind::Air && !base.bottom.eta) base.bottom.eta = material.bottom_eta();
  std::vector<Material> envelopes;
  for (const StackedLayer& layer : stack_layers(material)) {
    Material m = base;
    m.albedo = layer.albedo;
    m.g = layer.g;
    envelopes.push_back(m);
    if (layer.interface && layer.interface->eta != 1.0) {
      m.sigma = layer.interface->sigma;
      m.eta = std::max(layer.interface->eta, 1.0 / layer.interface->eta);
      envelopes.push_back(m);
    }
  }
  return envelopes;
}

Resolution choose_layer_resolution(const Material& material, const SolveOptions& options) {
  validate(material);
  const LayerGeometry geometry = classify_layer(material);
  const double forwardness = 1.0 - std::abs(material.g);
  const double sigma_min = std::min(geometry.top_open ? 1.0 : material.sigma,
                                    geometry.base == LayerBase::Rough ? material.bottom_sigma() : 1.0);
  Resolution resolution{};
  // N >= 6/sigma keeps the node quadrature of the interface lobes energy-conserving (docs/model.md §4.2); half of
  // layerlab's full-sphere HG heuristic 8.6/(1-g) - 0.2 resolves the phase function.
  const int from_phase = ceil_to_int(0.5 * (8.6 / forwardness - 0.2));
  const int from_surface = sigma_min < 1.0 ? ceil_to_int(6.0 / sigma_min) : 6;
  if (material.ordinates) {
    // Fewer ordinates than this create energy (up to 4x at N = 4, sigma = 0.2) or lose the real eigen-structure.
    const int minimum = std::max({4, from_surface, ceil_to_int(0.5 * from_phase)});
    if (*material.ordinates < minimum) {
      throw ParameterError("ordinates = " + std::to_string(*material.ordinates) + " is too few for this material; " +
                           "valid range is [" + std::to_string(minimum) +
                           ", 256] here (at least 6/sigma for the interfaces and (8.6/(1-|g|) - 0.2)/4 for g)");
    }
    resolution.ordinates = *material.ordinates;
  } else {
    // With a rough interface the exit sums the interface lobe over the ordinates: 16 leave a ripple of 1.5-4% across
    // exit angles (sigma 0.5-1, g <= 0.6); 24 bring it under 0.2% up to sigma 0.7, and 32 under 0.5% beyond.
    const bool rough = !geometry.top_open || geometry.base == LayerBase::Rough;
    const double sigma_max = std::max(geometry.top_open ? 0.0 : material.sigma,
                                      geometry.base == LayerBase::Rough ? material.bottom_sigma() : 0.0);
    // A transparent layer lets most light cross it unscattered or scattered once, so the radiance meeting the top
    // from inside stays directional, and its exit near the critical angle (grazing outside) needs finer nodes:
    // against N = 160, thin layers (g 0.5, Omega 0.99, sigma 0.2-1, light at 45 and 75 degrees) err in the binned
    // BRDF by up to 0.31% at T 0.6 and 1.3% at T 0.99 with 24 ordinates, 0.25% and 0.49% with 32, 0.24% at T 0.99
    // with 40.
    const double transparency = material.transparency();
    const int thin_floor = !rough ? 0 : transparency > 0.8 ? 40 : transparency > 0.5 ? 32 : 0;
    const int floor = std::max(!rough ? 16 : sigma_max > 0.7 ? 32 : 24, thin_floor);
    // A multiple of 4 at or above the need, at most 64 for the phase function, but never below the interfaces'
    // minimum (120 at sigma 0.05): fewer than 6/sigma would break the quadrature of the interface lobes.
    const auto multiple_of_4 = [](int n) { return (n + 3) / 4 * 4; };
    const int needed = std::max({floor, from_phase, from_surface});
    resolution.ordinates = std::max({std::min(multiple_of_4(needed), 64), multiple_of_4(from_surface),
                                     multiple_of_4(refracted_lobe_ordinates(geometry))});
  }
  resolution.max_modes =
      options.max_modes > 0
          ? options.max_modes
          : std::clamp(std::max({24, ceil_to_int(5.4 / forwardness) + 2, ceil_to_int(4.0 / sigma_min)}), 24, 128);
  // The preview keeps the default grid: its lobes are smeared by its ordinates anyway.
  resolution.table_size = options.table_size > 0 ? options.table_size
                          : options.preview      ? kDefaultTableSize
                                                 : lobe_table_size(material, geometry);
  // The interface operators are projected onto the mode cap rounded up to a multiple of 16 (Resolution).
  const auto interface_modes_for = [](int max_modes) { return max_modes == 1 ? 1 : (max_modes + 15) / 16 * 16; };
  resolution.interface_modes = interface_modes_for(resolution.max_modes);
  resolution.interface_azimuths = std::max({2 * resolution.interface_modes + 1, ceil_to_int(24.0 / sigma_min) + 1, 49});
  resolution.phase_azimuths = std::max({2 * resolution.max_modes + 1, ceil_to_int(20.0 / forwardness) + 1, 49});
  if (options.preview) {
    resolution.ordinates = std::min(resolution.ordinates, kPreviewResolution.ordinates);
    resolution.max_modes = std::min(resolution.max_modes, kPreviewResolution.max_modes);
    resolution.interface_modes = interface_modes_for(resolution.max_modes);
    resolution.interface_azimuths = std::clamp(kPreviewResolution.interface_azimuths,
                                               2 * resolution.interface_modes + 1, resolution.interface_azimuths);
  }
  return resolution;
}

}  // namespace

Resolution choose_resolution(const Material& material, const SolveOptions& options) {
  validate(material);
  if (material.below.empty()) return choose_layer_resolution(material, options);
  std::optional<Resolution> result;
  for (const Material& envelope : resolution_envelopes(material)) {
    const Resolution r = choose_layer_resolution(envelope, options);
    if (!result) {
      result = r;
      continue;
    }
    result->ordinates = std::max(result->ordinates, r.ordinates);
    result->max_modes = std::max(result->max_modes, r.max_modes);
    result->table_size = std::max(result->table_size, r.table_size);
    result->interface_modes = std::max(result->interface_modes, r.interface_modes);
    result->interface_azimuths = std::max(result->interface_azimuths, r.interface_azimuths);
    result->phase_azimuths = std::max(result->phase_azimuths, r.phase_azimuths);
  }
  return *result;
}

bool preview_is_coarser(const Material& material) {
  SolveOptions preview;
  preview.preview = true;
  const Resolution full = choose_resolution(material);
  const Resolution coarse = choose_resolution(material, preview);
  return coarse.ordinates < full.ordinates || coarse.max_modes < full.max_modes ||
         coarse.interface_azimuths < full.interface_azimuths || coarse.table_size < full.table_size;
}

}  // namespace skinlayer
