// docs/model.md §21.4, §21.9, §21.11 and §21.14: slabs at one lateral frequency joined through their faces, under an
// open, rough or smooth top and over a matched or smooth bottom, and the fluxes out of the stack.
#include "core/spatial/lateral_frequency_response.h"

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/series/quadrature.h"
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

  // Column c's solution at node row `row` and depth t in the slab.
  std::complex<double> column(int c, int row, double t) const {
    const std::complex<double> rate = modes.lambda(c);
    const int h = static_cast<int>(modes.lambda.size()) / 2;
    return modes.vectors(row, c) * std::exp(-rate * (c < h ? t : t - tau));
  }
  double particular(int row, double t) const { return beam == 0.0 ? 0.0 : beam * modes.beam(row) * std::exp(-t); }
};

// The solve with the albedo in the scattering operator scaled by operator_scale (1, or 0 for the first order in Omega
// of a collimated beam, whose source keeps its albedo).
LateralFrequencyResponse stack_response(std::span<const LateralSlab> slabs, double operator_scale,
                                        const LateralTopInterface* top, const LateralSmoothFace* bottom, double k,
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
  check(bottom == nullptr || bottom->reflection.size() == resolution.ordinates,
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
    s.tau = slab.tau;
    s.offset = unknowns;
    s.count = std::isinf(slab.tau) ? h : n;
    s.beam = collimated * std::exp(-above);
    unknowns += s.count;
    above += slab.tau;
    solved.push_back(std::move(s));
  }
  if (solved.empty()) return {};

  // Boundary conditions (one row each). At the top, u-(0) = t12 + R21 u+(0) under a rough top, mode by mode (the i^m
  // factor is the same on both sides, and t12 is mode 0 alone), and nothing enters going down under an open one.
  // Between slabs every node radiance is continuous. Under a finite last slab, u+(tau) = F_b u-(tau) at a smooth
  // bottom, and nothing enters going up over an index-matched half-space. (The collimated beam's own reflection at a
  // smooth bottom, e^{-tau} F_b(1) of it, is left out: §21.14.)
  Eigen::MatrixXcd B = Eigen::MatrixXcd::Zero(unknowns, unknowns);
  Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(unknowns);
  int equation = 0;
  const SolvedSlab& first = solved.front();
  for (int m = 0; m < M; ++m) {
    for (int i = 0; i < N; ++i) {
      const int row = layout.at(m, 0, i);
      for (int c = 0; c < first.count; ++c) B(equation, first.offset + c) = first.column(c, row, 0.0);
      rhs(equation) = -first.particular(row, 0.0);
      if (top != nullptr) {
        const Eigen::MatrixXd& reflect = top->reflection[static_cast<std::size_t>(m)];
        for (int j = 0; j < N; ++j) {
          const int from = layout.at(m, 1, j);
          for (int c = 0; c < first.count; ++c)
            B(equation, first.offset + c) -= reflect(i, j) * first.column(c, from, 0.0);
          rhs(equation) += reflect(i, j) * first.particular(from, 0.0);
        }
        if (m == 0) rhs(equation) += top->source(i);
      }
      ++equation;
    }
  }
  for (std::size_t l = 0; l + 1 < solved.size(); ++l) {
    const SolvedSlab &upper = solved[l], &lower = solved[l + 1];
    if (lower.face == nullptr) {
      for (int row = 0; row < n; ++row) {
        for (int c = 0; c < upper.count; ++c) B(equation, upper.offset + c) = upper.column(c, row, upper.tau);
        for (int c = 0; c < lower.count; ++c) B(equation, lower.offset + c) = -lower.column(c, row, 0.0);
        rhs(equation++) = lower.particular(row, 0.0) - upper.particular(row, upper.tau);
      }
      continue;
    }
    // A rough interface between them, mode by mode (lateral_internal_face.h): up-going above is R_a (down above) +
    // T_up (up below), down-going below is R_b (up below) + T_down (down above). No collimated beam reaches it.
    const LateralInternalFace& face = *lower.face;
    for (int m = 0; m < M; ++m) {
      const std::size_t mode = static_cast<std::size_t>(m);
      for (const bool up : {true, false}) {
        const SolvedSlab& own = up ? upper : lower;  // the side whose outgoing radiance the row sets
        const SolvedSlab& other = up ? lower : upper;
        const double own_depth = up ? upper.tau : 0.0, other_depth = up ? 0.0 : upper.tau;
        const Eigen::MatrixXd& reflect = up ? face.reflect_above[mode] : face.reflect_below[mode];
        const Eigen::MatrixXd& transmit = up ? face.transmit_up[mode] : face.transmit_down[mode];
        for (int i = 0; i < N; ++i) {
          const int row = layout.at(m, up ? 1 : 0, i);
          for (int c = 0; c < own.count; ++c) B(equation, own.offset + c) = own.column(c, row, own_depth);
          for (int j = 0; j < N; ++j) {
            const int towards = layout.at(m, up ? 0 : 1, j);  // the face: down above it, up below it
            const int from = layout.at(m, up ? 1 : 0, j);     // through it: up from below, down from above
            for (int c = 0; c < own.count; ++c)
              B(equation, own.offset + c) -= reflect(i, j) * own.column(c, towards, own_depth);
            for (int c = 0; c < other.count; ++c)
              B(equation, other.offset + c) -= transmit(i, j) * other.column(c, from, other_depth);
          }
          ++equation;
        }
      }
    }
  }
  const SolvedSlab& last = solved.back();
  const bool semi_infinite = std::isinf(last.tau);
  if (!semi_infinite) {
    for (int m = 0; m < M; ++m) {
      for (int i = 0; i < N; ++i) {
        const int row = layout.at(m, 1, i), down = layout.at(m, 0, i);
        const double reflect = bottom ? bottom->reflection(i) : 0.0;
        for (int c = 0; c < last.count; ++c) {
          B(equation, last.offset + c) = last.column(c, row, last.tau) - reflect * last.column(c, down, last.tau);
        }
        rhs(equation++) = -last.particular(row, last.tau) + reflect * last.particular(down, last.tau);
      }
    }
  }
  const Eigen::VectorXcd coefficients = B.partialPivLu().solve(rhs);

  // Fluxes out of the faces: mode 0 only, 2 pi sum_j a_j mu_j I(mu_j) times the fraction that crosses the face.
  const auto mode0_flux = [&](const SolvedSlab& slab, int up, double depth) {
    std::complex<double> flux = 0.0;
    for (int i = 0; i < N; ++i) {
      const int row = layout.at(0, up, i);
      std::complex<double> value = slab.particular(row, depth);
      for (int c = 0; c < slab.count; ++c) value += coefficients(slab.offset + c) * slab.column(c, row, depth);
      const double crossing = up == 1 ? (top ? top->exit(i) : 1.0) : (bottom ? bottom->exit(i) : 1.0);
      flux += q.weights[i] * q.nodes[i] * crossing * value;
    }
    return 2.0 * kPi * flux.real();
  };
  LateralFrequencyResponse response;
  response.reflectance = mode0_flux(first, 1, 0.0);
  if (!semi_infinite) response.transmittance = mode0_flux(last, 0, last.tau);
  return response;
}

}  // namespace

LateralFrequencyResponse lateral_stack_response(std::span<const LateralSlab> slabs, const LateralTopInterface* top,
                                                double k, const LateralFrequencyResolution& resolution,
                                                const LateralSmoothFace* bottom,
                                                std::span<const std::optional<LateralInternalFace>> faces) {
  return stack_response(slabs, 1.0, top, bottom, k, resolution, faces);
}

LateralFrequencyResponse collimated_single_scattering_response(std::span<const LateralSlab> slabs,
                                                               const LateralTopInterface* top, double k,
                                                               const LateralFrequencyResolution& resolution,
                                                               const LateralSmoothFace* bottom) {
  // The faces let the light out as they do, and send none of it back.
  std::optional<LateralTopInterface> letting_out;
  if (top != nullptr) {
    letting_out = *top;
    for (Eigen::MatrixXd& mode : letting_out->reflection) mode.setZero();
  }
  std::optional<LateralSmoothFace> leaving;
  if (bottom != nullptr) leaving = LateralSmoothFace{Eigen::VectorXd::Zero(bottom->exit.size()), bottom->exit};
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
