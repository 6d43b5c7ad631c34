#include "core/solver.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

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

std::vector<double> clamped_cosines(std::span<const double> mu) {
  std::vector<double> result(mu.begin(), mu.end());
  for (double& m : result) m = std::max(m, kMinCosine);
  return result;
}

// The interface kernels of a solve, from the caller's cache where it has them (options.cache); a build that is
// cancelled part-way throws before anything is cached.
std::shared_ptr<const InterfaceKernels> kernels_for(const Material& material, const Resolution& resolution,
                                                    std::span<const double> mu_in, std::span<const double> mu_out,
                                                    const SolveOptions& options, KernelSet set = KernelSet::All) {
  InterfaceKernelKey key{classify_layer(material),
                         resolution.ordinates,
                         resolution.interface_modes,
                         resolution.interface_azimuths,
                         clamped_cosines(mu_in),
                         clamped_cosines(mu_out),
                         set};
  const auto build = [&] {
    return interface_kernels(key.geometry, key.ordinates, key.modes, key.azimuths, key.mu_in, key.mu_out,
                             options.parallel_for, key.set, options.cancelled);
  };
  if (options.cache == nullptr) return std::make_shared<const InterfaceKernels>(build());
  return options.cache->interface_kernels(key, build);
}

}  // namespace

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
  const auto kernels = kernels_for(material, resolution, grid, grid, options,
                                   options.exact_unscattered ? KernelSet::AllButSurfaceMultiple : KernelSet::All);
  const std::shared_ptr<const MultipleScatteringLobe> lobes[] = {kernels->top_multiple, kernels->bottom_multiple};
  const UnscatteredLight unscattered =
      options.exact_unscattered ? UnscatteredLight(material, lobes) : UnscatteredLight();
  // One layer is a stack of one: core/solve/stack_solver.h solves both. The channels share it.
  const StackSolver solver(material, resolution, kernels, unscattered.path(), options.exact_unscattered, options.cache,
                           options.parallel_for, options.cancelled);
  struct ModeTables {
    Eigen::MatrixXd reflection, transmission;
  };
  const auto solve_mode = [&](int m, int channel) -> ModeTables {
    StackSolver::ModeResult r = solver.solve_mode(m, layer_albedos(channels[static_cast<std::size_t>(channel)]));
    return {std::move(r.reflection), std::move(r.transmission)};
  };
  const auto check_cancelled = [&options] { throw_if_cancelled(options.cancelled); };
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
      bounce.microfacet = material.microfacet;
      bounce.sigma = unscattered.top().sigma;
      bounce.eta = unscattered.top().eta;
      bounce.tau = unscattered.tau();
      bounce.bottom.sigma = unscattered.bottom().sigma;
      bounce.bottom.eta = 1.0 / unscattered.bottom().eta;
    }
    const auto coarse_kernels =
        internal ? kernels_for(bounce, resolution, grid, grid, options, KernelSet::BottomBounce) : kernels;
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
    const auto fine = kernels_for(bounce, finer, grid, grid, options, KernelSet::BottomBounce);
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
  return microfacet_brdf(top_interface(material), wi, wo);
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

}  // namespace

std::vector<std::vector<DirectionalAlbedo>> directional_albedo(std::span<const Material> channels,
                                                               std::span<const double> theta_i,
                                                               const SolveOptions& options) {
  if (channels.empty()) return {};
  check_channels(channels);
  // Mode 0 alone, of one layer or of a stack alike (core/solve/stack_solver.h), for every channel.
  const Material& material = channels.front();
  const Resolution resolution = flux_resolution(material, options);
  const std::vector<double> mu0 = cosines_of(theta_i);
  const StackSolver solver(material, resolution, kernels_for(material, resolution, mu0, {}, options),
                           UnscatteredPath::None, false, options.cache, options.parallel_for, options.cancelled);
  std::vector<std::vector<DirectionalAlbedo>> result;
  for (const Material& channel : channels) {
    std::vector<DirectionalAlbedo> rows = solver.directional_albedo(solver.solve_mode(0, layer_albedos(channel)));
    for (std::size_t k = 0; k < rows.size(); ++k) rows[k].theta_i = theta_i[k];
    result.push_back(std::move(rows));
  }
  return result;
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
