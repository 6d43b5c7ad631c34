#include "core/solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/boundary_solve.h"
#include "core/conventions.h"
#include "core/henyey_greenstein.h"
#include "core/interface_albedo.h"
#include "core/interface_operators.h"
#include "core/microfacet.h"
#include "core/quadrature.h"
#include "core/slab_eigen.h"
#include "core/unscattered_light.h"

namespace skinlayer {
namespace {

// Omega = 1 makes mode 0's eigen-reduction singular (a double eigenvalue k = 0). Solving at Omega = 1 - 1e-9 keeps
// it positive definite; the energy this absorbs is ~1e-9 per unit optical path (about 1e-4 of the albedo of a
// conservative semi-infinite layer, whose mean path length diverges).
constexpr double kMaxSolvedAlbedo = 1.0 - 1e-9;
// Exterior cosines are kept off 0 (grazing) so that 1/mu stays finite; the tables' theta = 90 deg row is the limit.
constexpr double kMinCosine = 1e-6;
constexpr int kDefaultTableSize = 48;

enum class Base { Rough, Open, Lambert };

struct Geometry {
  bool top_open;  // eta = 1: no top interface, the incident beam enters unscattered
  Base base;
  RoughDielectric top;
  RoughDielectric bottom;
  bool bottom_mirrors_top;  // bottom interface is the top one mirrored: R23 = R21 and T23 = T21
};

Geometry classify(const Material& material) {
  Geometry geometry{};
  geometry.top_open = material.eta == 1.0;
  geometry.top = {material.eta, material.sigma};
  switch (material.bottom.kind) {
    case BottomKind::Air:
      geometry.base = material.bottom_eta() == 1.0 ? Base::Open : Base::Rough;
      break;
    case BottomKind::Matched:
      geometry.base = Base::Open;
      break;
    case BottomKind::Lambert:
      geometry.base = Base::Lambert;
      break;
  }
  geometry.bottom = {1.0 / material.bottom_eta(), material.bottom_sigma()};
  geometry.bottom_mirrors_top = geometry.base == Base::Rough && material.bottom_eta() == material.eta &&
                                material.bottom_sigma() == material.sigma;
  return geometry;
}

std::vector<double> negated(std::span<const double> values) {
  std::vector<double> result(values.begin(), values.end());
  for (double& v : result) v = -v;
  return result;
}

Eigen::VectorXd attenuation(std::span<const double> mu0, double tau) {  // e^{-tau/mu0}
  Eigen::VectorXd result(static_cast<Eigen::Index>(mu0.size()));
  for (std::size_t k = 0; k < mu0.size(); ++k) result(static_cast<Eigen::Index>(k)) = std::exp(-tau / mu0[k]);
  return result;
}

// Generalized reciprocity of the radiance BTDF (Walter et al. 2007): f_t12(a -> b) / n2^2 = f_t21(b -> a) / n1^2.
// The reversed pair of propagation directions has the same azimuth difference, so the coefficients of the exit
// kernel (layer -> air, mu_j up to mu_o up) are those of the source kernel (air -> layer, -mu_o to -mu_j) / eta^2.
FourierKernel transmission_by_reciprocity(const FourierKernel& air_to_layer, double eta) {
  FourierKernel layer_to_air(air_to_layer.size());
  for (std::size_t m = 0; m < air_to_layer.size(); ++m) layer_to_air[m] = air_to_layer[m].transpose() / (eta * eta);
  return layer_to_air;
}

// The accurate albedos (interface_albedo) of an interface for light arriving along each cosine, with the direction
// back toward the light (sin theta, 0, z_sign cos theta) in the interface's frame. That frame has +z up: into the
// air for the top (light from the air: z_sign +1; from inside the layer: -1) and into the layer for the bottom (light
// from inside the layer: +1).
std::vector<InterfaceAlbedo> interface_albedos_along(const RoughDielectric& interface, std::span<const double> cosines,
                                                     double z_sign) {
  std::vector<Vec3> toward_light;
  toward_light.reserve(cosines.size());
  for (const double mu : cosines) {
    toward_light.emplace_back(std::sqrt(std::max(0.0, 1.0 - mu * mu)), 0.0, z_sign * std::abs(mu));
  }
  return interface_albedo(interface, toward_light);
}

std::vector<double> reflectances(const std::vector<InterfaceAlbedo>& albedos) {
  std::vector<double> result;
  for (const InterfaceAlbedo& a : albedos) result.push_back(a.reflectance);
  return result;
}

std::vector<double> transmittances(const std::vector<InterfaceAlbedo>& albedos) {
  std::vector<double> result;
  for (const InterfaceAlbedo& a : albedos) result.push_back(a.transmittance);
  return result;
}

// All Fourier-projected ingredients shared by the modes of one solve, and the per-mode solve itself.
class LayerSolver {
 public:
  // mu_in: the outside directions light arrives along; mu_out: those the tables leave along, either none (fluxes
  // only) or the same as mu_in (the exit operators are the source operators by reciprocity).
  // exact_unscattered: leave out of the exit sums the paths that UnscatteredLight evaluates exactly.
  LayerSolver(const Material& material, const Resolution& resolution, std::span<const double> mu_in,
              std::span<const double> mu_out, bool exact_unscattered = false);

  struct ModeResult {
    Eigen::MatrixXd reflection;    // K_out x K_in, graphics azimuth convention, 1/sr
    Eigen::MatrixXd transmission;  // K_out x K_in
    NodeField field;
  };
  // Mode m for single-scattering albedo `albedo` (everything projected at construction is albedo-independent).
  ModeResult solve_mode(int m, double albedo) const;

  const QuadratureRule& quadrature() const { return quadrature_; }
  const Geometry& geometry() const { return geometry_; }
  // Per node, the albedos of the top interface for light travelling up to it and of the bottom interface for light
  // travelling down to it (R = 0, T = 1 where there is no interface): the energy targets of R21 and R23.
  const std::vector<InterfaceAlbedo>& top_inside() const { return top_inside_; }
  const std::vector<InterfaceAlbedo>& bottom_inside() const { return bottom_inside_; }

 private:
  Eigen::MatrixXd lambert_reflection() const;

  Geometry geometry_;
  double tau_;
  double lambert_;
  QuadratureRule quadrature_;
  std::vector<InterfaceAlbedo> top_inside_, bottom_inside_;
  std::vector<double> mu_in_, mu_out_;
  Eigen::VectorXd beam_attenuation_;  // e^{-tau/mu0} per incident direction
  Eigen::VectorXd beam_flux_;         // F = 1/mu0 (so that E_perp mu0 = 1: values are BSDFs)
  bool want_exit_;
  UnscatteredPath exact_path_ = UnscatteredPath::None;  // the unscattered path left out of the exit sums
  Eigen::VectorXd node_attenuation_;                     // e^{-tau/mu_j} per node
  PhaseMatrices phase_;
  FourierKernel r_top_, t_source_, t_exit_, t_source_exterior_, r_top_rows_;
  FourierKernel r_bottom_, t_bottom_exit_, s_bottom_beam_, t_bottom_beam_, r_bottom_rows_, r_bottom_beam_rows_;
  FourierKernel beam_up_nodes_, beam_down_nodes_, same_rows_, opposite_rows_, beam_rows_up_, beam_rows_down_;
};

LayerSolver::LayerSolver(const Material& material, const Resolution& resolution, std::span<const double> mu_in,
                         std::span<const double> mu_out, bool exact_unscattered)
    : geometry_(classify(material)),
      tau_(material.tau),
      lambert_(material.bottom.lambert_albedo),
      quadrature_(double_gauss_half_range(resolution.ordinates)),
      top_inside_(quadrature_.size(), InterfaceAlbedo{0.0, 1.0}),
      bottom_inside_(quadrature_.size(), InterfaceAlbedo{0.0, 1.0}),
      mu_in_(mu_in.begin(), mu_in.end()),
      mu_out_(mu_out.begin(), mu_out.end()),
      want_exit_(!mu_out.empty()) {
  for (double& mu : mu_in_) mu = std::max(mu, kMinCosine);
  for (double& mu : mu_out_) mu = std::max(mu, kMinCosine);
  beam_attenuation_ = attenuation(mu_in_, tau_);
  node_attenuation_ = attenuation(quadrature_.nodes, tau_);
  if (exact_unscattered && want_exit_) exact_path_ = UnscatteredLight(material).path();
  beam_flux_ =
      Eigen::Map<const Eigen::VectorXd>(mu_in_.data(), static_cast<Eigen::Index>(mu_in_.size())).cwiseInverse();

  const CosineProjector surface(resolution.max_modes, resolution.interface_azimuths);
  const CosineProjector phase(resolution.max_modes, resolution.phase_azimuths);
  const std::span<const double> up = quadrature_.nodes;
  const std::span<const double> weights = quadrature_.weights;
  const std::vector<double> down = negated(up);
  const std::vector<double> down_in = negated(mu_in_);
  const std::vector<double> down_out = negated(mu_out_);
  const bool exterior_scattering = want_exit_ && (geometry_.top_open || geometry_.base == Base::Open);

  phase_ = henyey_greenstein_matrices(material.g, up, weights, phase);
  if (!geometry_.top_open) {
    r_top_ = interface_fourier(geometry_.top, up, down, surface);
    top_inside_ = interface_albedos_along(geometry_.top, up, -1.0);
    match_reflection_energy(r_top_, up, weights, reflectances(top_inside_));
    apply_quadrature_weights(r_top_, up, weights);
    t_source_ = interface_fourier(geometry_.top, down_in, down, surface);
    match_column_energy(t_source_, up, weights, transmittances(interface_albedos_along(geometry_.top, mu_in_, 1.0)));
    if (want_exit_) {
      // By reciprocity the exit operator inherits the energy matching of the source columns, row by row.
      t_exit_ = transmission_by_reciprocity(t_source_, material.eta);
      apply_quadrature_weights(t_exit_, up, weights);
      if (geometry_.base == Base::Open) {
        t_source_exterior_ = interface_fourier(geometry_.top, down_in, down_out, surface);
        r_top_rows_ = interface_fourier(geometry_.top, up, down_out, surface);
        apply_quadrature_weights(r_top_rows_, up, weights);
      }
    }
  } else {
    beam_up_nodes_ = henyey_greenstein_fourier(material.g, down_in, up, phase);
    beam_down_nodes_ = henyey_greenstein_fourier(material.g, down_in, down, phase);
    if (exterior_scattering) {
      beam_rows_up_ = henyey_greenstein_fourier(material.g, down_in, mu_out_, phase);
      beam_rows_down_ = henyey_greenstein_fourier(material.g, down_in, down_out, phase);
    }
  }
  if (exterior_scattering) {
    same_rows_ = henyey_greenstein_fourier(material.g, up, mu_out_, phase);
    opposite_rows_ = henyey_greenstein_fourier(material.g, down, mu_out_, phase);
  }
  if (geometry_.base == Base::Rough) {
    if (geometry_.bottom_mirrors_top && !geometry_.top_open) {
      r_bottom_ = r_top_;
      t_bottom_exit_ = t_exit_;
      bottom_inside_ = top_inside_;
    } else {
      r_bottom_ = interface_fourier(geometry_.bottom, down, up, surface);
      bottom_inside_ = interface_albedos_along(geometry_.bottom, up, 1.0);
      match_reflection_energy(r_bottom_, up, weights, reflectances(bottom_inside_));
      apply_quadrature_weights(r_bottom_, up, weights);
      if (want_exit_) {
        // As for the top: the exit rows are the transposed source columns from the air below (propagating up), each
        // matched to its slope-space transmittance. A sharp, low-contrast bottom (sigma3 0.2, eta3 1.2) has an
        // interior lobe ~ sigma3 (1 - 1/eta3) wide, narrower than the node spacing: its unmatched node sums ripple
        // by percents across exit angles.
        FourierKernel from_below = interface_fourier(geometry_.bottom, mu_out_, up, surface);
        match_column_energy(from_below, up, weights,
                            transmittances(interface_albedos_along(geometry_.bottom, mu_out_, -1.0)));
        t_bottom_exit_ = transmission_by_reciprocity(from_below, material.bottom_eta());
        apply_quadrature_weights(t_bottom_exit_, up, weights);
      }
    }
    if (geometry_.top_open) {
      s_bottom_beam_ = interface_fourier(geometry_.bottom, down_in, up, surface);
      match_column_energy(s_bottom_beam_, up, weights,
                          reflectances(interface_albedos_along(geometry_.bottom, mu_in_, 1.0)));
      if (want_exit_) {
        t_bottom_beam_ = interface_fourier(geometry_.bottom, down_in, down_out, surface);
        r_bottom_rows_ = interface_fourier(geometry_.bottom, down, mu_out_, surface);
        apply_quadrature_weights(r_bottom_rows_, up, weights);
        r_bottom_beam_rows_ = interface_fourier(geometry_.bottom, down_in, mu_out_, surface);
      }
    }
  }
}

// Lambertian base, f = A/pi, mode 0 only: R(o, j) = c_0 (A/pi) mu_j a_j = 2 A mu_j a_j.
Eigen::MatrixXd LayerSolver::lambert_reflection() const {
  const Eigen::Index n = quadrature_.size();
  Eigen::RowVectorXd row(n);
  for (Eigen::Index j = 0; j < n; ++j) row(j) = 2.0 * lambert_ * quadrature_.nodes[j] * quadrature_.weights[j];
  return row.replicate(n, 1);
}

LayerSolver::ModeResult LayerSolver::solve_mode(int m, double albedo) const {
  const bool conservative = albedo == 1.0;
  const double solved_albedo = std::min(albedo, kMaxSolvedAlbedo);
  const std::span<const double> nodes = quadrature_.nodes;
  const std::span<const double> weights = quadrature_.weights;
  const Eigen::Index n = quadrature_.size();
  const Eigen::Index count_in = static_cast<Eigen::Index>(mu_in_.size());
  const Eigen::Index count_out = static_cast<Eigen::Index>(mu_out_.size());
  const double scattering = solved_albedo * fourier_azimuth_weight(m);
  SlabEigenSolution eigen = slab_eigen(nodes, weights, phase_.same[m], phase_.opposite[m], scattering);
  if (m == 0 && conservative && std::isinf(tau_)) {
    // Conservative scattering in a semi-infinite slab: the slowest mode of the clamped albedo tends to the exact
    // bounded solution k = 0, u = constant (exact on the quadrature, since mode 0's phase matrix conserves energy).
    eigen.k(0) = 0.0;
    eigen.g_up.col(0).setOnes();
    eigen.g_down.col(0).setOnes();
  }
  const bool lambert_mode = geometry_.base == Base::Lambert && m == 0;
  const bool infinite = std::isinf(tau_);

  BoundaryProblem problem;
  problem.eigen = &eigen;
  problem.tau = tau_;
  if (!geometry_.top_open) {
    problem.reflect_top = r_top_[m];
    problem.source_top = t_source_[m];
  }
  if (geometry_.base == Base::Rough) {
    problem.reflect_bottom = r_bottom_[m];
    if (geometry_.top_open) problem.source_bottom = s_bottom_beam_[m] * beam_attenuation_.asDiagonal();
  } else if (lambert_mode) {
    problem.reflect_bottom = lambert_reflection();
    if (geometry_.top_open) {
      problem.source_bottom = (lambert_ * kInvPi) * beam_attenuation_.transpose().replicate(n, 1);
    }
  }
  BeamParticular beam;
  if (geometry_.top_open) {
    Eigen::MatrixXd source_up = solved_albedo * beam_up_nodes_[m] * beam_flux_.asDiagonal();
    Eigen::MatrixXd source_down = solved_albedo * beam_down_nodes_[m] * beam_flux_.asDiagonal();
    if (m == 0) {
      // Scale the beam's first-scattering source so that the quadrature scatters exactly the energy it removes:
      // c_0 sum_j a_j (p^0(mu_j, -mu0) + p^0(-mu_j, -mu0)) = 1, as mode 0's phase matrix does between nodes.
      const Eigen::Map<const Eigen::VectorXd> a(weights.data(), n);
      for (Eigen::Index k = 0; k < count_in; ++k) {
        const double scattered =
            fourier_azimuth_weight(0) * a.dot(beam_up_nodes_[0].col(k) + beam_down_nodes_[0].col(k));
        source_up.col(k) /= scattered;
        source_down.col(k) /= scattered;
      }
    }
    beam = beam_particular_solution(nodes, weights, phase_.same[m], phase_.opposite[m], scattering, source_up,
                                    source_down, mu_in_);
    problem.beam = &beam;
  }

  ModeResult result;
  result.field = solve_boundary(problem, static_cast<int>(count_in));
  const NodeField& field = result.field;
  if (!want_exit_) return result;

  ExitScattering exit{mu_out_, {}, {}, {}};
  if (!same_rows_.empty()) {
    const Eigen::Map<const Eigen::VectorXd> a(weights.data(), n);
    exit.same_row = scattering * same_rows_[m] * a.asDiagonal();
    exit.opposite_row = scattering * opposite_rows_[m] * a.asDiagonal();
  }

  // Out through the top.
  if (!geometry_.top_open) {
    result.reflection = t_exit_[m] * field.up_top;
  } else {
    Eigen::MatrixXd upward_at_bottom;
    if (!infinite && geometry_.base == Base::Rough) {
      upward_at_bottom = r_bottom_rows_[m] * field.down_bottom;
      // The beam reflected by the bottom without scattering: UnscatteredLight::brdf, unless kept here.
      if (exact_path_ != UnscatteredPath::BottomOnly) {
        upward_at_bottom += r_bottom_beam_rows_[m] * beam_attenuation_.asDiagonal();
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
    exit.beam_row = solved_albedo * beam_rows_up_[m] * beam_flux_.asDiagonal();
    result.reflection = upward_radiance_at_top(problem, field, exit, upward_at_bottom);
  }

  // Out through the bottom.
  if (infinite || geometry_.base == Base::Lambert) {
    result.transmission = Eigen::MatrixXd::Zero(count_out, count_in);
  } else if (geometry_.base == Base::Rough) {
    result.transmission = t_bottom_exit_[m] * field.down_bottom;
    // The light that crossed both interfaces unscattered, t23 e^{-tau/mu_j} t12, is on the nodes as the first-pass
    // part of down_bottom (exactly: the discrete-ordinate equations propagate it without scattering); it and the
    // open top's beam through the bottom are UnscatteredLight::btdf when evaluated exactly.
    if (exact_path_ == UnscatteredPath::TopThenBottom) {
      result.transmission -= t_bottom_exit_[m] * (node_attenuation_.asDiagonal() * t_source_[m]);
    }
    if (geometry_.top_open && exact_path_ != UnscatteredPath::BottomOnly) {
      result.transmission += t_bottom_beam_[m] * beam_attenuation_.asDiagonal();
    }
  } else {
    Eigen::MatrixXd downward_at_top;
    if (!geometry_.top_open) {
      downward_at_top = r_top_rows_[m] * field.up_top;
      // The light refracted by the top straight through to the matched bottom: UnscatteredLight::btdf, unless kept.
      if (exact_path_ != UnscatteredPath::TopOnly) downward_at_top += t_source_exterior_[m];
    } else {
      exit.beam_row = solved_albedo * beam_rows_down_[m] * beam_flux_.asDiagonal();
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

// The refracted lobe of a rough interface, seen from inside, is about w = sigma (1 - 1/eta) radians wide (a facet
// tilt of sigma turns the refracted ray by that much less than it turns the normal). Where the lobe falls between
// the ordinates the exit sums ripple across exit angles; measured against N = 192 (BSDF averaged over 15-degree
// bins, both interfaces, eta 1.05-1.4, sigma 0.2-0.5): N w = 1.2 leaves 0.3-3%, N w = 1.6 0.2-0.5%, N w = 1.75
// under 0.06%. So N >= 1.75 / w, which is 6.1/sigma at eta 1.4 and grows without bound as eta -> 1; at most 128
// (0.15-0.4 s per solve on the 2-core VM): near-matched interfaces (eta < 1.07 at sigma 0.2) keep a ripple of
// ~0.3% there.
int refracted_lobe_ordinates(const Geometry& geometry) {
  const auto need = [](const RoughDielectric& interface) {
    const double n = std::max(interface.eta, 1.0 / interface.eta);  // the bottom's eta is n_below / n_layer
    return ceil_to_int(std::min(1.75 / (interface.sigma * (1.0 - 1.0 / n)), 128.0));
  };
  int result = 0;
  if (!geometry.top_open) result = need(geometry.top);
  if (geometry.base == Base::Rough) result = std::max(result, need(geometry.bottom));
  return result;
}

}  // namespace

Resolution choose_resolution(const Material& material, const SolveOptions& options) {
  validate(material);
  const Geometry geometry = classify(material);
  const double forwardness = 1.0 - std::abs(material.g);
  const double sigma_min =
      std::min(geometry.top_open ? 1.0 : material.sigma, geometry.base == Base::Rough ? material.bottom_sigma() : 1.0);
  Resolution resolution{};
  // N >= 6/sigma keeps the node quadrature of the interface lobes energy-conserving (model-spec §4.1); half of
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
    const bool rough = !geometry.top_open || geometry.base == Base::Rough;
    const double sigma_max = std::max(geometry.top_open ? 0.0 : material.sigma,
                                      geometry.base == Base::Rough ? material.bottom_sigma() : 0.0);
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
  resolution.table_size = options.table_size > 0 ? options.table_size : kDefaultTableSize;
  resolution.interface_azimuths = std::max({2 * resolution.max_modes + 1, ceil_to_int(24.0 / sigma_min) + 1, 49});
  resolution.phase_azimuths = std::max({2 * resolution.max_modes + 1, ceil_to_int(20.0 / forwardness) + 1, 49});
  return resolution;
}

namespace {

// The tables for one resolution and several albedos (the projections are shared); `converged` tells whether every
// Fourier series met its tolerance before the cap.
struct TableSolve {
  std::vector<LayerTables> tables;
  bool converged;
};

TableSolve solve_tables(const Material& material, std::span<const double> albedos, const Resolution& resolution,
                        double tolerance, bool exact_unscattered) {
  const int k = resolution.table_size;
  std::vector<double> grid(k);
  for (int i = 0; i < k; ++i) grid[i] = std::cos(LayerTables::grid_angle(i, k));
  const LayerSolver solver(material, resolution, grid, grid, exact_unscattered);
  const UnscatteredLight unscattered = exact_unscattered ? UnscatteredLight(material) : UnscatteredLight();

  const std::size_t plane = static_cast<std::size_t>(k) * k;
  TableSolve result{{}, true};
  for (const double albedo : albedos) {
    std::vector<double> reflection, transmission;
    reflection.reserve(plane * resolution.max_modes);
    transmission.reserve(plane * resolution.max_modes);
    double peak_reflection = 0.0, peak_transmission = 0.0;
    int quiet_modes = 0;
    int modes = 0;
    for (int m = 0; m < resolution.max_modes && quiet_modes < 2; ++m) {
      const LayerSolver::ModeResult mode = solver.solve_mode(m, albedo);
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
    result.converged = result.converged && quiet_modes >= 2;
    result.tables.emplace_back(k, modes, std::move(reflection), std::move(transmission), unscattered);
  }
  return result;
}

void check_albedos(std::span<const double> albedos) {
  for (const double albedo : albedos) check_parameter(parameter_info("albedo"), albedo);
}

}  // namespace

std::vector<LayerTables> solve(const Material& material, std::span<const double> albedos, const SolveOptions& options) {
  check_albedos(albedos);
  Resolution resolution = choose_resolution(material, options);
  if (resolution.table_size < 4) {
    throw ParameterError("table_size = " + std::to_string(resolution.table_size) +
                         " is out of range; it must be at least 4");
  }
  // The automatic cap on Fourier modes suits most materials; thin, strongly forward-scattering layers seen near
  // grazing need more, so an unconverged series is solved again with twice the cap (up to 256 modes).
  TableSolve result = solve_tables(material, albedos, resolution, options.fourier_tolerance, options.exact_unscattered);
  while (!result.converged && options.max_modes == 0 && resolution.max_modes < 256) {
    SolveOptions doubled = options;
    doubled.max_modes = 2 * resolution.max_modes;
    resolution = choose_resolution(material, doubled);
    result = solve_tables(material, albedos, resolution, options.fourier_tolerance, options.exact_unscattered);
  }
  return std::move(result.tables);
}

LayerTables solve(const Material& material, const SolveOptions& options) {
  return std::move(solve(material, std::span<const double>(&material.albedo, 1), options).front());
}

double brdf_surface(const Material& material, double theta_i, double theta_o, double phi) {
  const Vec3 wi = direction_from_angles(theta_i, 0.0);
  const Vec3 wo = direction_from_angles(theta_o, phi);
  return microfacet_brdf({material.eta, material.sigma}, wi, wo);
}

std::vector<std::vector<DirectionalAlbedo>> directional_albedo(const Material& material,
                                                               std::span<const double> theta_i,
                                                               std::span<const double> albedos,
                                                               const SolveOptions& options) {
  check_albedos(albedos);
  SolveOptions mode_zero = options;
  mode_zero.max_modes = 1;  // hemispherical fractions need only the azimuthal mean
  const Resolution resolution = choose_resolution(material, mode_zero);
  std::vector<double> mu0(theta_i.size());
  for (std::size_t k = 0; k < theta_i.size(); ++k) mu0[k] = std::cos(theta_i[k]);
  const LayerSolver solver(material, resolution, mu0, {});
  const Geometry& geometry = solver.geometry();
  const QuadratureRule& q = solver.quadrature();

  // Energy transmittance of each interface from inside, per node: light travelling up (top) or down (bottom).
  const std::vector<InterfaceAlbedo>& top_inside = solver.top_inside();
  const std::vector<InterfaceAlbedo>& bottom_inside = solver.bottom_inside();
  const bool direct_path = geometry.top_open && !std::isinf(material.tau);
  std::vector<std::vector<DirectionalAlbedo>> result;
  for (const double albedo : albedos) {
    const LayerSolver::ModeResult mode = solver.solve_mode(0, albedo);
    std::vector<DirectionalAlbedo> rows;
    for (std::size_t k = 0; k < theta_i.size(); ++k) {
      const Eigen::Index col = static_cast<Eigen::Index>(k);
      const Vec3 wi = direction_from_angles(theta_i[k], 0.0);
      DirectionalAlbedo row{};
      row.theta_i = theta_i[k];
      const InterfaceAlbedo entry = interface_albedo(geometry.top, wi);
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
        if (geometry.base == Base::Rough) row.interface_loss += down_flux * bottom_inside[j].loss();
      }
      row.reflectance_subsurface = up;
      const double direct = direct_path ? std::exp(-material.tau / std::max(mu0[k], kMinCosine)) : 0.0;
      switch (geometry.base) {
        case Base::Lambert:
          row.transmittance = 0.0;
          break;
        case Base::Open:
          row.transmittance = down + direct;
          break;
        case Base::Rough: {
          const double sin0 = std::sqrt(std::max(0.0, 1.0 - mu0[k] * mu0[k]));
          const InterfaceAlbedo beam_exit =
              direct > 0.0 ? interface_albedo(geometry.bottom, Vec3(sin0, 0.0, mu0[k])) : InterfaceAlbedo{0.0, 0.0};
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

std::vector<DirectionalAlbedo> directional_albedo(const Material& material, std::span<const double> theta_i,
                                                  const SolveOptions& options) {
  return std::move(
      directional_albedo(material, theta_i, std::span<const double>(&material.albedo, 1), options).front());
}

}  // namespace skinlayer
