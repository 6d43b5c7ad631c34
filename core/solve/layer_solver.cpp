#include "core/solve/layer_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/conventions.h"
#include "core/medium/henyey_greenstein.h"
#include "core/medium/slab_eigen.h"
#include "core/series/quadrature.h"
#include "core/solve/solve_cache.h"
#include "core/unscattered/bottom_bounce.h"

namespace skinlayer {

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

}  // namespace skinlayer
