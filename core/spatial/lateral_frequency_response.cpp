// docs/model.md §21.4, §21.9, §21.11, §21.14, §21.16 and §21.17: slabs at one lateral frequency joined through their
// faces (continuous, or a rough interface), under an open, rough or smooth top and over a matched half-space or a
// bottom face (§21.17), and the fluxes out of the stack.
#include "core/spatial/lateral_frequency_response.h"

#include <Eigen/Dense>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/series/quadrature.h"
#include "core/spatial/lateral_bottom_face.h"
#include "core/spatial/lateral_internal_face.h"
#include "core/spatial/lateral_slab_modes.h"
#include "core/spatial/lateral_top_interface.h"

namespace skinlayer {
namespace {

void check(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("lateral_stack_response: " + message);
}

// One slab of the solve: its modes, its depth, where its unknowns start, and the collimated beam's flux at its top.
struct SolvedSlab {
  LateralSlabModes modes;
  double tau = 0.0;
  int offset = 0;  // the first unknown: decaying modes (weights referred to the top), then growing ones (to the bottom)
  int count = 0;   // n, or n / 2 for a semi-infinite slab (decaying only)
  double beam = 0;  // the collimated beam's flux at the slab's top (open or smooth top), else 0
  const LateralInternalFace* face = nullptr;  // a rough interface above the slab (not the first's), else none

  // Every column's real solution at every node row at depth t (n x count), and the particular solution there.
  Eigen::MatrixXd values(double t) const { return modes.real_solutions(t, tau, count); }
  Eigen::VectorXd particulars(double t) const {
    return beam == 0.0 ? Eigen::VectorXd::Zero(modes.vectors.rows())
                       : Eigen::VectorXd(beam * std::exp(-t) * modes.beam);
  }
};

// A conservative half-space at k = 0 (slab_eigen.h): the clamped albedo's slowest decaying mode gives way to the exact
// bounded solution, isotropic radiance of mode 0 (lambda = 0), as in the BSDF solve.
void take_bounded_mode(LateralSlabModes& modes, const LateralLayout& layout) {
  const Eigen::Index h = modes.lambda.size() / 2;
  Eigen::Index slowest = 0;
  modes.lambda.head(h).cwiseAbs().minCoeff(&slowest);
  modes.lambda(slowest) = 0.0;
  modes.vectors.col(slowest).setZero();
  for (int up = 0; up < 2; ++up) {
    for (int j = 0; j < layout.nodes; ++j) modes.vectors(layout.at(0, up, j), slowest) = 1.0;
  }
  modes.imaginary[static_cast<std::size_t>(slowest)] = false;
}

// The solve with the albedo in the scattering operator scaled by operator_scale (1, or 0 for the first order in Omega
// of a collimated beam, whose source keeps its albedo).
LateralFrequencyResponse stack_response(std::span<const LateralSlab> slabs, double operator_scale,
                                        const LateralTopInterface* top, const LateralBottomFace* bottom, double k,
                                        const LateralFrequencyResolution& resolution,
                                        std::span<const std::optional<LateralInternalFace>> faces = {}) {
  check(!slabs.empty(), "needs at least one slab");
  check(k >= 0.0 && std::isfinite(k), "k must be finite and >= 0");
  check(resolution.ordinates >= 2 && resolution.azimuth_modes >= 1, "resolution needs >= 2 ordinates and >= 1 mode");
  for (std::size_t l = 0; l < slabs.size(); ++l) {
    check(slabs[l].tau >= 0.0, "tau must be >= 0");
    check(std::isfinite(slabs[l].tau) || l + 1 == slabs.size(), "only the last slab can be semi-infinite");
    check(slabs[l].relative_extinction > 0.0 && std::isfinite(slabs[l].relative_extinction),
          "the relative extinction must be finite and > 0");
  }
  if (top != nullptr) {
    check(top->source.size() == resolution.ordinates && top->exit.size() == resolution.ordinates &&
              static_cast<int>(top->reflection.size()) >= resolution.azimuth_modes,
          "the top interface's operators were built for another resolution");
  }
  check(bottom == nullptr || (bottom->exit.size() == resolution.ordinates &&
                              static_cast<int>(bottom->reflection.size()) >= resolution.azimuth_modes),
        "the bottom face was built for another resolution");
  check(faces.empty() || faces.size() == slabs.size(), "needs one entry of faces per slab");
  for (std::size_t l = 0; l < faces.size(); ++l) {
    if (!faces[l]) continue;
    check(l > 0, "the first slab's face is the top");
    check(slabs[l].tau > 0.0, "a slab under an interface needs tau > 0");
    check(static_cast<int>(faces[l]->reflect_above.size()) >= resolution.azimuth_modes &&
              faces[l]->reflect_above.front().rows() == resolution.ordinates,
          "an interface between slabs was built for another resolution");
    check(top != nullptr && top->collimated == 0.0,
          "interfaces between slabs take light that enters as node radiance (a rough top, or diffuse light)");
  }
  const double collimated = top ? top->collimated : 1.0;  // the beam's flux inside, at the top
  const QuadratureRule q = double_gauss_half_range(resolution.ordinates);
  const LateralLayout layout{resolution.ordinates, resolution.azimuth_modes};
  const int N = layout.nodes, M = layout.modes, n = layout.size(), h = n / 2;

  std::vector<SolvedSlab> solved;
  int unknowns = 0;
  double above = 0.0;  // optical depth above the slab
  for (std::size_t l = 0; l < slabs.size(); ++l) {
    const LateralSlab& slab = slabs[l];
    if (slab.tau == 0.0) continue;
    SolvedSlab s;
    s.face = faces.empty() || !faces[l] ? nullptr : &*faces[l];
    // k is per mean free path of the first slab; in this slab's own it is k mu_t,first / mu_t.
    s.modes = lateral_slab_modes(operator_scale * slab.albedo, collimated > 0.0 ? slab.albedo : 0.0, slab.g,
                                 k / slab.relative_extinction, q, M);
    if (std::isinf(slab.tau) && k == 0.0 && operator_scale * slab.albedo == 1.0) take_bounded_mode(s.modes, layout);
    s.tau = slab.tau;
    s.offset = unknowns;
    s.count = std::isinf(slab.tau) ? h : n;
    s.beam = collimated * std::exp(-above);
    unknowns += s.count;
    above += slab.tau;
    solved.push_back(std::move(s));
  }
  if (solved.empty()) return {};

  // An index-matched half-space under the stack is eliminated through its reflection (below): its unknowns are not
  // in the system.
  const SolvedSlab& last = solved.back();
  const bool semi_infinite = std::isinf(last.tau);
  const bool eliminate_last = semi_infinite && solved.size() >= 2 && last.face == nullptr;
  if (eliminate_last) unknowns = last.offset;

  // Boundary conditions (one row each), filled block by block from each slab's solutions at its faces. At the top,
  // u-(0) = t12 + R21 u+(0) under a rough top, mode by mode (the i^m factor is the same on both sides, and t12 is mode
  // 0 alone), and nothing enters going down under an open one. Between slabs every node radiance is continuous, or an
  // interface joins them. Under a finite last slab, u+(tau) = R23 u-(tau) at a bottom face, mode by mode, and nothing
  // enters going up over an index-matched half-space. (The collimated beam's own reflection at a bottom face, e^{-tau}
  // of it, is left out: §21.14.)
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(unknowns, unknowns);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  const auto rows = [&](int m, int up) { return layout.at(m, up, 0); };  // the first of a mode's N rows one way
  int equation = 0;
  // An outer face of `slab` at `depth`, mode by mode: the radiance going in (direction `in`: 0 down, 1 up) is what the
  // face reflects of the radiance going out (none where `reflection` is null), plus `source` in mode 0.
  const auto outer_face = [&](const SolvedSlab& slab, double depth, int in,
                              const std::vector<Eigen::MatrixXd>* reflection, const Eigen::VectorXd* source) {
    const Eigen::MatrixXd values = slab.values(depth);
    const Eigen::VectorXd beam = slab.particulars(depth);
    const int out = 1 - in;
    for (int m = 0; m < M; ++m) {
      auto block = B.block(equation, slab.offset, N, slab.count);
      block = values.middleRows(rows(m, in), N);
      rhs.segment(equation, N) = -beam.segment(rows(m, in), N);
      if (reflection != nullptr) {
        const Eigen::MatrixXd& reflect = (*reflection)[static_cast<std::size_t>(m)];
        block -= reflect * values.middleRows(rows(m, out), N);
        rhs.segment(equation, N) += reflect * beam.segment(rows(m, out), N);
      }
      if (m == 0 && source != nullptr) rhs.segment(equation, N) += *source;
      equation += N;
    }
  };
  const SolvedSlab& first = solved.front();
  outer_face(first, 0.0, 0, top ? &top->reflection : nullptr, top ? &top->source : nullptr);
  for (std::size_t l = 0; l + 1 < solved.size(); ++l) {
    const SolvedSlab &upper = solved[l], &lower = solved[l + 1];
    const Eigen::MatrixXd upper_face = upper.values(upper.tau), lower_face = lower.values(0.0);
    const Eigen::VectorXd beam_above = upper.particulars(upper.tau), beam_below = lower.particulars(0.0);
    if (eliminate_last && l + 2 == solved.size()) {
      // The half-space's decaying solutions V at its top, split by direction, give its reflection R = V_up V_down^-1.
      // With c its weights and x the rest, continuity U x + p_U = V c + p_L makes, on the up rows,
      //   (U_up - R U_down) x = R (p_U,down - p_L,down) + p_L,up - p_U,up.
      Eigen::MatrixXd down(h, h), up(h, h), upper_down(h, upper.count), upper_up(h, upper.count);
      Eigen::VectorXd gap_down(h), gap_up(h);  // p_U - p_L
      for (int m = 0; m < M; ++m) {
        down.middleRows(m * N, N) = lower_face.middleRows(rows(m, 0), N);
        up.middleRows(m * N, N) = lower_face.middleRows(rows(m, 1), N);
        upper_down.middleRows(m * N, N) = upper_face.middleRows(rows(m, 0), N);
        upper_up.middleRows(m * N, N) = upper_face.middleRows(rows(m, 1), N);
        gap_down.segment(m * N, N) = beam_above.segment(rows(m, 0), N) - beam_below.segment(rows(m, 0), N);
        gap_up.segment(m * N, N) = beam_above.segment(rows(m, 1), N) - beam_below.segment(rows(m, 1), N);
      }
      const Eigen::MatrixXd reflection = down.transpose().partialPivLu().solve(up.transpose()).transpose();
      B.block(equation, upper.offset, h, upper.count) = upper_up - reflection * upper_down;
      rhs.segment(equation, h) = reflection * gap_down - gap_up;
      equation += h;
      continue;
    }
    if (lower.face == nullptr) {
      B.block(equation, upper.offset, n, upper.count) = upper_face;
      B.block(equation, lower.offset, n, lower.count) = -lower_face;
      rhs.segment(equation, n) = beam_below - beam_above;
      equation += n;
      continue;
    }
    // A rough interface between them, mode by mode (lateral_internal_face.h): up-going above is R_a (down above) +
    // T_up (up below), down-going below is R_b (up below) + T_down (down above). No collimated beam reaches it.
    const LateralInternalFace& face = *lower.face;
    for (int m = 0; m < M; ++m) {
      const std::size_t mode = static_cast<std::size_t>(m);
      B.block(equation, upper.offset, N, upper.count) =
          upper_face.middleRows(rows(m, 1), N) - face.reflect_above[mode] * upper_face.middleRows(rows(m, 0), N);
      B.block(equation, lower.offset, N, lower.count) = -face.transmit_up[mode] * lower_face.middleRows(rows(m, 1), N);
      equation += N;
      B.block(equation, lower.offset, N, lower.count) =
          lower_face.middleRows(rows(m, 0), N) - face.reflect_below[mode] * lower_face.middleRows(rows(m, 1), N);
      B.block(equation, upper.offset, N, upper.count) =
          -face.transmit_down[mode] * upper_face.middleRows(rows(m, 0), N);
      equation += N;
    }
  }
  if (!semi_infinite) outer_face(last, last.tau, 1, bottom ? &bottom->reflection : nullptr, nullptr);
  check(equation == unknowns, "the boundary system is not square");
  const Eigen::VectorXd coefficients = B.partialPivLu().solve(rhs);

  // Fluxes out of the faces: mode 0 only, 2 pi sum_j a_j mu_j I(mu_j) times the fraction that crosses the face.
  const auto mode0_flux = [&](const SolvedSlab& slab, int up, double depth) {
    const Eigen::VectorXd radiance =
        slab.values(depth) * coefficients.segment(slab.offset, slab.count) + slab.particulars(depth);
    double flux = 0.0;
    for (int i = 0; i < N; ++i) {
      const double crossing = up == 1 ? (top ? top->exit(i) : 1.0) : (bottom ? bottom->exit(i) : 1.0);
      flux += q.weights[i] * q.nodes[i] * crossing * radiance(layout.at(0, up, i));
    }
    return 2.0 * kPi * flux;
  };
  LateralFrequencyResponse response;
  response.reflectance = mode0_flux(first, 1, 0.0);
  if (!semi_infinite) response.transmittance = mode0_flux(last, 0, last.tau);
  return response;
}

}  // namespace

StackDepths stack_depths(std::span<const LateralSlab> slabs) {
  StackDepths depths;
  for (const LateralSlab& slab : slabs) {
    depths.optical.push_back(depths.tau);
    depths.geometric.push_back(depths.height);
    depths.tau += slab.tau;
    depths.height += slab.tau / slab.relative_extinction;
  }
  return depths;
}

LateralFrequencyResponse lateral_stack_response(std::span<const LateralSlab> slabs, const LateralTopInterface* top,
                                                double k, const LateralFrequencyResolution& resolution,
                                                const LateralBottomFace* bottom,
                                                std::span<const std::optional<LateralInternalFace>> faces) {
  return stack_response(slabs, 1.0, top, bottom, k, resolution, faces);
}

LateralFrequencyResponse collimated_single_scattering_response(std::span<const LateralSlab> slabs,
                                                               const LateralTopInterface* top, double k,
                                                               const LateralFrequencyResolution& resolution,
                                                               const LateralBottomFace* bottom) {
  // The faces let the light out as they do, and send none of it back.
  std::optional<LateralTopInterface> letting_out;
  if (top != nullptr) {
    letting_out = *top;
    for (Eigen::MatrixXd& mode : letting_out->reflection) mode.setZero();
  }
  std::optional<LateralBottomFace> leaving;
  if (bottom != nullptr) {
    leaving = *bottom;
    for (Eigen::MatrixXd& mode : leaving->reflection) mode.setZero();
  }
  return stack_response(slabs, 0.0, letting_out ? &*letting_out : nullptr, leaving ? &*leaving : nullptr, k,
                        resolution);
}

LateralFrequencyResponse rough_top_lateral_response(double tau, double albedo, double g, const LateralTopInterface& top,
                                                    double k, const LateralFrequencyResolution& resolution) {
  const LateralSlab slab{tau, albedo, g};
  return stack_response({&slab, 1}, 1.0, &top, nullptr, k, resolution);
}

LateralFrequencyResponse open_layer_lateral_response(double tau, double albedo, double g, double k,
                                                     const LateralFrequencyResolution& resolution) {
  const LateralSlab slab{tau, albedo, g};
  return stack_response({&slab, 1}, 1.0, nullptr, nullptr, k, resolution);
}

LateralFrequencyResponse open_layer_single_scattering_response(double tau, double albedo, double g, double k,
                                                               const LateralFrequencyResolution& resolution) {
  const LateralSlab slab{tau, albedo, g};
  return stack_response({&slab, 1}, 0.0, nullptr, nullptr, k, resolution);
}

}  // namespace skinlayer
