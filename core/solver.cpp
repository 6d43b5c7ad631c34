#include "core/solver.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>

#include "core/conventions.h"
#include "core/interfaces/interface_albedo.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/interfaces/microfacet.h"
#include "core/medium/henyey_greenstein.h"
#include "core/medium/slab_eigen.h"
#include "core/series/quadrature.h"
#include "core/solve/boundary_solve.h"
#include "core/solve/solve_cache.h"
#include "core/solve/stack_solver.h"
#include "core/unscattered/bottom_bounce.h"
#include "core/unscattered/unscattered_light.h"

namespace skinlayer {
namespace {

// Exterior cosines are kept off 0 (grazing) so that 1/mu stays finite; the tables' theta = 90 deg row is the limit.
constexpr double kMinCosine = 1e-6;
constexpr int kDefaultTableSize = 48;

std::vector<double> clamped_cosines(std::span<const double> mu) {
  std::vector<double> result(mu.begin(), mu.end());
  for (double& m : result) m = std::max(m, kMinCosine);
  return result;
}

// The interface kernels of a solve, from the caller's cache where it has them.
std::shared_ptr<const InterfaceKernels> kernels_for(const Material& material, const Resolution& resolution,
                                                    std::span<const double> mu_in, std::span<const double> mu_out,
                                                    SolveCache* cache, const ParallelFor& parallel_for,
                                                    KernelSet set = KernelSet::All) {
  InterfaceKernelKey key{classify_layer(material),
                         resolution.ordinates,
                         resolution.interface_modes,
                         resolution.interface_azimuths,
                         clamped_cosines(mu_in),
                         clamped_cosines(mu_out),
                         set};
  const auto build = [&] {
    return interface_kernels(key.geometry, key.ordinates, key.modes, key.azimuths, key.mu_in, key.mu_out, parallel_for,
                             key.set);
  };
  if (cache == nullptr) return std::make_shared<const InterfaceKernels>(build());
  return cache->interface_kernels(key, build);
}

// The per-mode solve over shared interface kernels, with the albedo-independent medium terms (the phase function's
// projections and the beam's attenuation) of one material.
class LayerSolver {
 public:
  // The outside directions are the kernels' (mu_in: light arrives along; mu_out: the tables leave along, none for
  // fluxes only). exact_path: the unscattered path (UnscatteredLight::path) left out of the exit sums, because the
  // caller evaluates it exactly; None keeps every path on the ordinates.
  LayerSolver(const Material& material, const Resolution& resolution, std::shared_ptr<const InterfaceKernels> kernels,
              UnscatteredPath exact_path, SolveCache* cache);

  struct ModeResult {
    Eigen::MatrixXd reflection;    // K_out x K_in, graphics azimuth convention, 1/sr
    Eigen::MatrixXd transmission;  // K_out x K_in
    NodeField field;
  };
  // Mode m for single-scattering albedo `albedo` (everything projected at construction is albedo-independent).
  ModeResult solve_mode(int m, double albedo) const;

  const InterfaceKernels& kernels() const { return *kernels_; }

 private:
  std::shared_ptr<const InterfaceKernels> kernels_;
  const LayerGeometry& geometry_;
  const QuadratureRule& quadrature_;
  double tau_;
  double lambert_;
  const std::vector<double>& mu_in_;
  const std::vector<double>& mu_out_;
  Eigen::VectorXd beam_attenuation_;  // e^{-tau/mu0} per incident direction
  Eigen::VectorXd beam_flux_;         // F = 1/mu0 (so that E_perp mu0 = 1: values are BSDFs)
  bool want_exit_;
  UnscatteredPath exact_path_;        // the unscattered path left out of the exit sums
  Eigen::VectorXd node_attenuation_;  // e^{-tau/mu_j} per node
  std::shared_ptr<const PhaseKernels> phase_kernels_;
};

LayerSolver::LayerSolver(const Material& material, const Resolution& resolution,
                         std::shared_ptr<const InterfaceKernels> kernels, UnscatteredPath exact_path, SolveCache* cache)
    : kernels_(std::move(kernels)),
      geometry_(kernels_->geometry),
      quadrature_(kernels_->quadrature),
      tau_(material.tau),
      lambert_(material.bottom.lambert_albedo),
      mu_in_(kernels_->mu_in),
      mu_out_(kernels_->mu_out),
      want_exit_(!mu_out_.empty()),
      exact_path_(want_exit_ ? exact_path : UnscatteredPath::None) {
  beam_attenuation_ = slab_attenuation(mu_in_, tau_);
  node_attenuation_ = slab_attenuation(quadrature_.nodes, tau_);
  beam_flux_ =
      Eigen::Map<const Eigen::VectorXd>(mu_in_.data(), static_cast<Eigen::Index>(mu_in_.size())).cwiseInverse();

  const bool beam = geometry_.top_open;
  const bool exterior = want_exit_ && (geometry_.top_open || geometry_.base == LayerBase::Open);
  phase_kernels_ = cached_phase_kernels(cache, material.g, quadrature_, resolution.max_modes, resolution.phase_azimuths,
                                        mu_in_, mu_out_, beam, exterior);
}

LayerSolver::ModeResult LayerSolver::solve_mode(int m, double albedo) const {
  const double solved_albedo = std::min(albedo, kMaxSolvedAlbedo);
  const std::span<const double> nodes = quadrature_.nodes;
  const std::span<const double> weights = quadrature_.weights;
  const Eigen::Index n = quadrature_.size();
  const Eigen::Index count_in = static_cast<Eigen::Index>(mu_in_.size());
  const Eigen::Index count_out = static_cast<Eigen::Index>(mu_out_.size());
  const double scattering = solved_albedo * fourier_azimuth_weight(m);
  const SlabEigenSolution eigen = slab_mode_eigen(nodes, weights, phase_kernels_->phase.same[m],
                                                  phase_kernels_->phase.opposite[m], m, albedo, tau_);
  const bool lambert_mode = geometry_.base == LayerBase::Lambert && m == 0;
  const bool infinite = std::isinf(tau_);

  BoundaryProblem problem;
  problem.eigen = &eigen;
  problem.tau = tau_;
  if (!geometry_.top_open) {
    problem.reflect_top = kernels_->r_top[m];
    problem.source_top = kernels_->t_source[m];
  }
  if (geometry_.base == LayerBase::Rough) {
    problem.reflect_bottom = kernels_->r_bottom[m];
    if (geometry_.top_open) problem.source_bottom = kernels_->s_bottom_beam[m] * beam_attenuation_.asDiagonal();
  } else if (lambert_mode) {
    problem.reflect_bottom = lambert_reflection(quadrature_, lambert_);
    if (geometry_.top_open) {
      problem.source_bottom = (lambert_ * kInvPi) * beam_attenuation_.transpose().replicate(n, 1);
    }
  }
  BeamParticular beam;
  if (geometry_.top_open) {
    beam = beam_particular(*phase_kernels_, quadrature_, m, solved_albedo, mu_in_);
    problem.beam = &beam;
  }

  ModeResult result;
  result.field = solve_boundary(problem, static_cast<int>(count_in));
  const NodeField& field = result.field;
  if (!want_exit_) return result;

  ExitScattering exit{mu_out_, {}, {}, {}};
  if (!phase_kernels_->same_rows.empty()) {
    const Eigen::Map<const Eigen::VectorXd> a(weights.data(), n);
    exit.same_row = scattering * phase_kernels_->same_rows[m] * a.asDiagonal();
    exit.opposite_row = scattering * phase_kernels_->opposite_rows[m] * a.asDiagonal();
  }

  // Out through the top.
  if (!geometry_.top_open) {
    result.reflection = kernels_->t_exit[m] * field.up_top;
  } else {
    Eigen::MatrixXd upward_at_bottom;
    if (!infinite && geometry_.base == LayerBase::Rough) {
      upward_at_bottom = kernels_->r_bottom_rows[m] * field.down_bottom;
      // The beam reflected by the bottom without scattering: UnscatteredLight::brdf, unless kept here.
      if (exact_path_ != UnscatteredPath::BottomOnly) {
        upward_at_bottom += kernels_->r_bottom_beam_rows[m] * beam_attenuation_.asDiagonal();
      }
    } else if (!infinite && lambert_mode) {
      Eigen::RowVectorXd flux(count_in);  // diffuse plus direct flux reaching the base
      for (Eigen::Index k = 0; k < count_in; ++k) {
        double diffuse = 0.0;
        for (Eigen::Index j = 0; j < n; ++j) diffuse += 2.0 * kPi * nodes[j] * weights[j] * field.down_bottom(j, k);
        flux(k) = diffuse + beam_attenuation_(k);
      }
      upward_at_bottom = (lambert_ * kInvPi) * flux.replicate(count_out, 1);
    }
    exit.beam_row = solved_albedo * phase_kernels_->beam_rows_up[m] * beam_flux_.asDiagonal();
    result.reflection = upward_radiance_at_top(problem, field, exit, upward_at_bottom);
  }

  // Out through the bottom.
  if (infinite || geometry_.base == LayerBase::Lambert) {
    result.transmission = Eigen::MatrixXd::Zero(count_out, count_in);
  } else if (geometry_.base == LayerBase::Rough) {
    // The light that crossed both interfaces unscattered, t23 e^{-tau/mu_j} t12, is on the nodes as the first-pass
    // part of down_bottom (exactly: the discrete-ordinate equations propagate it without scattering); it and the
    // open top's beam through the bottom are UnscatteredLight::btdf when evaluated exactly, so it is taken off the
    // node field before the exit (one product instead of two).
    if (exact_path_ == UnscatteredPath::TopThenBottom) {
      result.transmission =
          kernels_->t_bottom_exit[m] * (field.down_bottom - node_attenuation_.asDiagonal() * kernels_->t_source[m]);
    } else {
      result.transmission = kernels_->t_bottom_exit[m] * field.down_bottom;
    }
    if (geometry_.top_open && exact_path_ != UnscatteredPath::BottomOnly) {
      result.transmission += kernels_->t_bottom_beam[m] * beam_attenuation_.asDiagonal();
    }
  } else {
    Eigen::MatrixXd downward_at_top;
    if (!geometry_.top_open) {
      downward_at_top = kernels_->r_top_rows[m] * field.up_top;
      // The light refracted by the top straight through to the matched bottom: UnscatteredLight::btdf, unless kept.
      if (exact_path_ != UnscatteredPath::TopOnly) downward_at_top += kernels_->t_source_exterior[m];
    } else {
      exit.beam_row = solved_albedo * phase_kernels_->beam_rows_down[m] * beam_flux_.asDiagonal();
    }
    if (!geometry_.top_open) exit.beam_row.resize(0, 0);
    result.transmission = downward_radiance_at_bottom(problem, field, exit, downward_at_top);
  }
  const double parity = azimuth_parity(m);
  result.reflection *= parity;
  result.transmission *= parity;
  return result;
}

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

namespace {

// The single-scattering albedo of each layer, top to bottom.
std::vector<double> layer_albedos(const Material& material) {
  std::vector<double> albedos;
  for (const StackedLayer& layer : stack_layers(material)) albedos.push_back(layer.albedo);
  return albedos;
}

// The tables for one resolution and several albedos (the projections are shared); `converged` tells whether every
// Fourier series met its tolerance before the cap.
struct TableSolve {
  std::vector<LayerTables> tables;
  bool converged;
};

TableSolve solve_tables(std::span<const Material> channels, const Resolution& resolution, const SolveOptions& options) {
  const Material& material = channels.front();
  const int k = resolution.table_size;
  std::vector<double> grid(k);
  for (int i = 0; i < k; ++i) grid[i] = std::cos(LayerTables::grid_angle(i, k));
  const UnscatteredLight unscattered = options.exact_unscattered ? UnscatteredLight(material) : UnscatteredLight();
  const auto kernels = kernels_for(material, resolution, grid, grid, options.cache, options.parallel_for);
  // One layer: the single-slab solve; a stack: core/solve/stack_solver.h. The channels share either.
  std::optional<LayerSolver> layer;
  std::optional<StackSolver> stack;
  if (material.below.empty()) {
    layer.emplace(material, resolution, kernels, unscattered.path(), options.cache);
  } else {
    stack.emplace(material, resolution, kernels, unscattered.path(), options.cache, options.parallel_for);
  }
  struct ModeTables {
    Eigen::MatrixXd reflection, transmission;
  };
  const auto solve_mode = [&](int m, int channel) -> ModeTables {
    const Material& c = channels[static_cast<std::size_t>(channel)];
    if (layer) {
      LayerSolver::ModeResult r = layer->solve_mode(m, c.albedo);
      return {std::move(r.reflection), std::move(r.transmission)};
    }
    StackSolver::ModeResult r = stack->solve_mode(m, layer_albedos(c));
    return {std::move(r.reflection), std::move(r.transmission)};
  };
  const auto check_cancelled = [&options] {
    if (options.cancelled && options.cancelled()) throw SolveCancelled();
  };
  check_cancelled();
  const double tolerance = options.fourier_tolerance;

  const std::size_t plane = static_cast<std::size_t>(k) * k;
  struct Coefficients {
    int modes = 0;
    std::vector<double> reflection, transmission;  // per mode, K x K with (o, i) at i K + o
  };
  std::vector<Coefficients> solved(channels.size());
  std::vector<char> converged(channels.size(), 0);
  // Several albedos run side by side (SolveOptions::parallel_for), each its modes in order. A single albedo runs
  // its modes side by side instead, kModeBlock at a time; the modes past the convergence point are discarded, so
  // the result is the serial one bit for bit.
  constexpr int kModeBlock = 4;
  const bool parallel_modes = channels.size() == 1 && options.parallel_for;
  const auto solve_albedo = [&](int index) {
    std::vector<double> reflection, transmission;
    reflection.reserve(plane * resolution.max_modes);
    transmission.reserve(plane * resolution.max_modes);
    double peak_reflection = 0.0, peak_transmission = 0.0;
    int quiet_modes = 0;
    int modes = 0;
    std::vector<ModeTables> block;  // modes block_start, block_start + 1, ...
    int block_start = 0;
    for (int m = 0; m < resolution.max_modes && quiet_modes < 2; ++m) {
      if (m == block_start + static_cast<int>(block.size())) {
        block_start = m;
        block.assign(static_cast<std::size_t>(parallel_modes ? std::min(kModeBlock, resolution.max_modes - m) : 1), {});
        const auto solve_one = [&](int b) {
          check_cancelled();
          block[static_cast<std::size_t>(b)] = solve_mode(block_start + b, index);
        };
        run_parallel(options.parallel_for, static_cast<int>(block.size()), solve_one);
      }
      const ModeTables& mode = block[static_cast<std::size_t>(m - block_start)];
      for (int i = 0; i < k; ++i) {
        for (int o = 0; o < k; ++o) {
          reflection.push_back(mode.reflection(o, i));
          transmission.push_back(mode.transmission(o, i));
        }
      }
      const double r = mode.reflection.cwiseAbs().maxCoeff();
      const double t = mode.transmission.cwiseAbs().maxCoeff();
      if (!std::isfinite(r) || !std::isfinite(t)) {
        throw std::runtime_error("solve: Fourier mode " + std::to_string(m) + " is not finite");
      }
      if (m == 0) {
        peak_reflection = r;
        peak_transmission = t;
      }
      const bool quiet = r <= tolerance * peak_reflection && t <= tolerance * peak_transmission;
      quiet_modes = quiet ? quiet_modes + 1 : 0;
      modes = m + 1;
    }
    converged[static_cast<std::size_t>(index)] = quiet_modes >= 2;
    solved[static_cast<std::size_t>(index)] = {modes, std::move(reflection), std::move(transmission)};
  };
  if (parallel_modes) {
    solve_albedo(0);
  } else {
    run_parallel(options.parallel_for, static_cast<int>(channels.size()), solve_albedo);
  }

  // The unscattered light's first reflection off a rough bottom, on finer ordinates where it matters
  // (core/unscattered/bottom_bounce.h): the tables' node image of it is replaced by the finer one, mode by mode. Not in
  // a preview, which is a quick look by definition.
  const auto refine_bottom_bounce = [&] {
    // The bounce off the path's second interface under the top (an interface between layers, or the bottom): the
    // image of a single layer with that interface as its bottom and the depth between them
    // (core/unscattered/bottom_bounce.h). Under an open top, where the path starts at an interface between layers, it
    // stays as solved.
    if (unscattered.path() != UnscatteredPath::TopThenBottom || options.preview || material.eta == 1.0) return;
    const bool internal = material.has_internal_interfaces();
    Material bounce = material;  // one layer, or a stack whose path ends at the bottom: the material's own kernels
    if (internal) {
      bounce = Material{};
      bounce.sigma = unscattered.top().sigma;
      bounce.eta = unscattered.top().eta;
      bounce.tau = unscattered.tau();
      bounce.bottom.sigma = unscattered.bottom().sigma;
      bounce.bottom.eta = 1.0 / unscattered.bottom().eta;
    }
    const auto coarse_kernels = internal ? kernels_for(bounce, resolution, grid, grid, options.cache,
                                                       options.parallel_for, KernelSet::BottomBounce)
                                         : kernels;
    const InterfaceKernels& coarse = *coarse_kernels;
    Resolution finer = resolution;
    finer.ordinates = bottom_bounce_ordinates(resolution.ordinates, coarse.geometry.top);
    if (finer.ordinates <= resolution.ordinates) return;
    const Eigen::VectorXd coarse_attenuation = slab_attenuation(coarse.quadrature.nodes, unscattered.tau());
    const Eigen::MatrixXd coarse_mode0 = bottom_bounce_image(coarse, coarse_attenuation, 0);
    std::vector<Eigen::MatrixXd> mode0;
    for (const Coefficients& c : solved) mode0.push_back(Eigen::Map<const Eigen::MatrixXd>(c.reflection.data(), k, k));
    if (!bottom_bounce_matters(coarse_mode0, mode0)) return;
    check_cancelled();
    const auto fine =
        kernels_for(bounce, finer, grid, grid, options.cache, options.parallel_for, KernelSet::BottomBounce);
    const Eigen::VectorXd fine_attenuation = slab_attenuation(fine->quadrature.nodes, unscattered.tau());
    int modes = 0;
    for (const Coefficients& c : solved) modes = std::max(modes, c.modes);
    for (int m = 0; m < modes; ++m) {
      const Eigen::MatrixXd correction =
          azimuth_parity(m) * (bottom_bounce_image(*fine, fine_attenuation, m) -
                               (m == 0 ? coarse_mode0 : bottom_bounce_image(coarse, coarse_attenuation, m)));
      for (Coefficients& c : solved) {
        if (m >= c.modes) continue;
        Eigen::Map<Eigen::MatrixXd>(c.reflection.data() + static_cast<std::size_t>(m) * plane, k, k) += correction;
      }
    }
  };
  refine_bottom_bounce();
  std::vector<LayerTables> tables;
  for (Coefficients& c : solved) {
    tables.emplace_back(k, c.modes, std::move(c.reflection), std::move(c.transmission), unscattered);
  }
  return {std::move(tables), std::ranges::all_of(converged, [](char c) { return c != 0; })};
}

void check_albedos(std::span<const double> albedos) {
  for (const double albedo : albedos) check_parameter(parameter_info("albedo"), albedo);
}

// The material once per first-layer albedo.
std::vector<Material> with_first_albedos(const Material& material, std::span<const double> albedos) {
  std::vector<Material> channels(albedos.size(), material);
  for (std::size_t c = 0; c < albedos.size(); ++c) channels[c].albedo = albedos[c];
  return channels;
}

// Channels must be valid and differ only in their layers' albedos.
void check_channels(std::span<const Material> channels) {
  for (const Material& c : channels) {
    validate(c);
    if (!differ_only_in_albedos(c, channels.front())) {
      throw std::invalid_argument("solve: the channels of one material may differ only in their albedos");
    }
  }
}

}  // namespace

std::vector<LayerTables> solve(std::span<const Material> channels, const SolveOptions& options) {
  if (channels.empty()) return {};
  check_channels(channels);
  // The resolution serves every channel: lobe_table_size judges the bottom's sharp reflection by the darkest one,
  // under which it stands out most.
  Material resolved = channels.front();
  for (const Material& c : channels) resolved.albedo = std::min(resolved.albedo, c.albedo);
  Resolution resolution = choose_resolution(resolved, options);
  if (resolution.table_size < 4) {
    throw ParameterError("table_size = " + std::to_string(resolution.table_size) +
                         " is out of range; it must be at least 4");
  }
  // The automatic cap on Fourier modes suits most materials; thin, strongly forward-scattering layers seen near
  // grazing need more, so an unconverged series is solved again with twice the cap (up to 256 modes).
  TableSolve result = solve_tables(channels, resolution, options);
  while (!result.converged && options.max_modes == 0 && !options.preview && resolution.max_modes < 256) {
    SolveOptions doubled = options;
    doubled.max_modes = 2 * resolution.max_modes;
    resolution = choose_resolution(resolved, doubled);
    result = solve_tables(channels, resolution, doubled);
  }
  return std::move(result.tables);
}

std::vector<LayerTables> solve(const Material& material, std::span<const double> albedos, const SolveOptions& options) {
  check_albedos(albedos);
  return solve(with_first_albedos(material, albedos), options);
}

LayerTables solve(const Material& material, const SolveOptions& options) {
  return std::move(solve(material, std::span<const double>(&material.albedo, 1), options).front());
}

double brdf_surface(const Material& material, double theta_i, double theta_o, double phi) {
  const Vec3 wi = direction_from_angles(theta_i, 0.0);
  const Vec3 wo = direction_from_angles(theta_o, phi);
  return microfacet_brdf({material.eta, material.sigma}, wi, wo);
}

namespace {

// The resolution of the directional albedos: hemispherical fractions need only the azimuthal mean, mode 0.
Resolution flux_resolution(const Material& material, const SolveOptions& options) {
  SolveOptions mode_zero = options;
  mode_zero.max_modes = 1;
  return choose_resolution(material, mode_zero);
}

std::vector<double> cosines_of(std::span<const double> theta) {
  std::vector<double> mu(theta.size());
  for (std::size_t k = 0; k < theta.size(); ++k) mu[k] = std::cos(theta[k]);
  return mu;
}

std::vector<std::vector<DirectionalAlbedo>> layer_directional_albedo(const Material& material,
                                                                     std::span<const double> theta_i,
                                                                     std::span<const double> albedos,
                                                                     const SolveOptions& options) {
  const Resolution resolution = flux_resolution(material, options);
  const std::vector<double> mu0 = cosines_of(theta_i);
  const LayerSolver solver(material, resolution,
                           kernels_for(material, resolution, mu0, {}, options.cache, options.parallel_for),
                           UnscatteredPath::None, options.cache);
  const LayerGeometry& geometry = solver.kernels().geometry;
  const QuadratureRule& q = solver.kernels().quadrature;

  // Energy transmittance of each interface from inside, per node: light travelling up (top) or down (bottom).
  const std::vector<InterfaceAlbedo>& top_inside = solver.kernels().top_inside;
  const std::vector<InterfaceAlbedo>& bottom_inside = solver.kernels().bottom_inside;
  const bool direct_path = geometry.top_open && !std::isinf(material.tau);
  // The interfaces' albedos for the incident directions, which no albedo changes: the top's for light from the air,
  // and the bottom's for the open top's beam reaching it unscattered.
  std::vector<Vec3> incident;
  for (const double theta : theta_i) incident.push_back(direction_from_angles(theta, 0.0));
  const std::vector<InterfaceAlbedo> entries = interface_albedo(geometry.top, incident);
  std::vector<Vec3> beam_at_bottom;
  for (const double mu : mu0) beam_at_bottom.emplace_back(std::sqrt(std::max(0.0, 1.0 - mu * mu)), 0.0, mu);
  const std::vector<InterfaceAlbedo> beam_exits = direct_path && geometry.base == LayerBase::Rough
                                                      ? interface_albedo(geometry.bottom, beam_at_bottom)
                                                      : std::vector<InterfaceAlbedo>(mu0.size(), {0.0, 0.0});
  std::vector<std::vector<DirectionalAlbedo>> result;
  for (const double albedo : albedos) {
    const LayerSolver::ModeResult mode = solver.solve_mode(0, albedo);
    std::vector<DirectionalAlbedo> rows;
    for (std::size_t k = 0; k < theta_i.size(); ++k) {
      const Eigen::Index col = static_cast<Eigen::Index>(k);
      DirectionalAlbedo row{};
      row.theta_i = theta_i[k];
      const InterfaceAlbedo& entry = entries[k];
      row.reflectance_surface = entry.reflectance;
      row.interface_loss = entry.loss();
      double up = 0.0, down = 0.0;
      for (int j = 0; j < q.size(); ++j) {
        const double flux_weight = 2.0 * kPi * q.nodes[j] * q.weights[j];
        const double up_flux = flux_weight * mode.field.up_top(j, col);
        const double down_flux = flux_weight * mode.field.down_bottom(j, col);
        up += up_flux * top_inside[j].transmittance;
        down += down_flux * bottom_inside[j].transmittance;
        row.interface_loss += up_flux * top_inside[j].loss();
        if (geometry.base == LayerBase::Rough) row.interface_loss += down_flux * bottom_inside[j].loss();
      }
      row.reflectance_subsurface = up;
      const double direct = direct_path ? std::exp(-material.tau / std::max(mu0[k], kMinCosine)) : 0.0;
      switch (geometry.base) {
        case LayerBase::Lambert:
          row.transmittance = 0.0;
          break;
        case LayerBase::Open:
          row.transmittance = down + direct;
          break;
        case LayerBase::Rough: {
          const InterfaceAlbedo beam_exit = direct > 0.0 ? beam_exits[k] : InterfaceAlbedo{0.0, 0.0};
          row.transmittance = down + direct * beam_exit.transmittance;
          row.interface_loss += direct * (direct > 0.0 ? beam_exit.loss() : 0.0);
          break;
        }
      }
      if (std::isinf(material.tau)) row.transmittance = 0.0;
      row.absorptance = 1.0 - row.reflectance() - row.transmittance;
      rows.push_back(row);
    }
    result.push_back(std::move(rows));
  }
  return result;
}

std::vector<std::vector<DirectionalAlbedo>> stack_directional_albedo(std::span<const Material> channels,
                                                                     std::span<const double> theta_i,
                                                                     const SolveOptions& options) {
  const Material& material = channels.front();
  const Resolution resolution = flux_resolution(material, options);
  const std::vector<double> mu0 = cosines_of(theta_i);
  const StackSolver solver(material, resolution,
                           kernels_for(material, resolution, mu0, {}, options.cache, options.parallel_for),
                           UnscatteredPath::None, options.cache, options.parallel_for);
  std::vector<std::vector<DirectionalAlbedo>> result;
  for (const Material& channel : channels) {
    std::vector<DirectionalAlbedo> rows = solver.directional_albedo(solver.solve_mode(0, layer_albedos(channel)));
    for (std::size_t k = 0; k < rows.size(); ++k) rows[k].theta_i = theta_i[k];
    result.push_back(std::move(rows));
  }
  return result;
}

}  // namespace

std::vector<std::vector<DirectionalAlbedo>> directional_albedo(std::span<const Material> channels,
                                                               std::span<const double> theta_i,
                                                               const SolveOptions& options) {
  if (channels.empty()) return {};
  check_channels(channels);
  if (!channels.front().below.empty()) return stack_directional_albedo(channels, theta_i, options);
  std::vector<double> albedos;
  for (const Material& c : channels) albedos.push_back(c.albedo);
  return layer_directional_albedo(channels.front(), theta_i, albedos, options);
}

std::vector<std::vector<DirectionalAlbedo>> directional_albedo(const Material& material,
                                                               std::span<const double> theta_i,
                                                               std::span<const double> albedos,
                                                               const SolveOptions& options) {
  check_albedos(albedos);
  return directional_albedo(with_first_albedos(material, albedos), theta_i, options);
}

std::vector<DirectionalAlbedo> directional_albedo(const Material& material, std::span<const double> theta_i,
                                                  const SolveOptions& options) {
  return std::move(
      directional_albedo(material, theta_i, std::span<const double>(&material.albedo, 1), options).front());
}

}  // namespace skinlayer
