// Discretized interface operators (Stam 2001's t12, R21, R23, ...): Fourier coefficients of a rough interface's
// BSDF between sets of propagation directions, and the radiance-to-radiance matrices built from them.
#pragma once

#include <span>
#include <vector>

#include "core/cancellation.h"
#include "core/interfaces/interface_albedo.h"
#include "core/interfaces/microfacet.h"
#include "core/series/fourier.h"

namespace skinlayer {

// f^m(d_from -> d_to) of the interface's full BSDF (reflection or transmission, whichever the signs imply), for
// signed propagation cosines. Per mode an (n_to x n_from) matrix, in 1/sr. `cancelled` is asked once per incident
// direction (core/cancellation.h).
FourierKernel interface_fourier(const RoughDielectric& interface, std::span<const double> mu_from,
                                std::span<const double> mu_to, const CosineProjector& projector,
                                const CancelCheck& cancelled = {});

// An interface's multiply scattered lobe (core/interfaces/multiple_scattering.h) between signed propagation cosines,
// mode by mode: per mode an (n_to x n_from) matrix in 1/sr, in propagation convention like interface_fourier (the
// lobe's graphics-convention modes times (-1)^m), as many modes as the lobe holds (none without an interface).
class MultipleScatteringLobe;
FourierKernel multiple_scattering_fourier(const MultipleScatteringLobe& lobe, std::span<const double> mu_from,
                                          std::span<const double> mu_to);

// An interface's kernel with its parts: `kernel` the whole BSDF (the single scattering and the multiply scattered
// lobe, summed mode by mode), `multiple` the lobe's share of the first modes alone (empty under
// MicrofacetModel::Single). Through one interface the exact unscattered light (core/unscattered/unscattered_light.h)
// holds both parts; through two it is single scattering only, so the solver takes its node image from kernel[m] -
// multiple[m] (core/solve/stack_solver.cpp).
struct InterfaceKernel {
  FourierKernel kernel;
  FourierKernel multiple;

  bool has_multiple() const { return !multiple.empty(); }
  // Whether mode m holds a multiply scattered part.
  bool has_multiple(int m) const { return m < static_cast<int>(multiple.size()); }
  // Mode m without its multiply scattered part: the single scattering alone.
  Eigen::MatrixXd single_scattering(int m) const;
  // The part of mode m that the tables carry, for a kernel from outside straight to outside directions (one
  // interface's reflection or transmission of the incident light): all of it, or none (null) where the exact
  // unscattered light replaces it (`exact`), the multiply scattered lobe with the single scattering.
  const Eigen::MatrixXd* carried_by_tables(int m, bool exact) const;
  std::size_t bytes() const;  // both parts' memory
};

// How an interface kernel's energy is matched, part by part, to the accurate albedos (interface_albedo_parts):
// per column to the reflectances or the transmittances (match_column_energy), between the nodes to the reflectances
// (match_reflection_energy), or, for rows to outside directions (no quadrature: they carry no energy of their own),
// not at all or the multiply scattered part alone, per column to its reflectance or transmittance by the lobe's own
// energy from that direction (ReflectedRows, TransmittedRows; match_multiple_rows).
enum class EnergyMatch { None, ReflectedColumns, TransmittedColumns, Reflection, ReflectedRows, TransmittedRows };

// The kernel from mu_from to mu_to: interface_fourier, plus the multiply scattered lobe under
// MicrofacetModel::Multiple, each part matched to its own share of `albedos` (one per column, along mu_from) over the
// quadrature `nodes` and `weights` (the rows), then summed. Without weights applied.
// `lobe` is the interface's multiply scattered lobe with projector.modes() modes, under MicrofacetModel::Multiple
// (one the caller builds once for all of an interface's kernels); null builds one.
InterfaceKernel matched_interface_kernel(const RoughDielectric& interface, std::span<const double> mu_from,
                                         std::span<const double> mu_to, const CosineProjector& projector,
                                         EnergyMatch match, std::span<const InterfaceAlbedoParts> albedos,
                                         std::span<const double> nodes, std::span<const double> weights,
                                         const CancelCheck& cancelled = {},
                                         const MultipleScatteringLobe* lobe = nullptr);
// Unmatched (EnergyMatch::None): to rows of outside directions.
InterfaceKernel interface_kernel(const RoughDielectric& interface, std::span<const double> mu_from,
                                 std::span<const double> mu_to, const CosineProjector& projector,
                                 const CancelCheck& cancelled = {}, const MultipleScatteringLobe* lobe = nullptr);

// Turns coefficients over quadrature directions (from = nodes with weights a_j) into operators that map node
// radiance to outgoing radiance:  K^m(o, j) = c_m f^m(mu_j -> mu_o) |mu_j| a_j  (dimensionless).
void apply_quadrature_weights(FourierKernel& kernel, std::span<const double> nodes, std::span<const double> weights);

// Energy matching of a kernel from outside directions into the nodes (rows = nodes, columns = outside directions,
// before apply_quadrature_weights): scales column k of every mode by  target[k] / (c_0 sum_j a_j |mu_j| f^0(j, k)),
// so that the node quadrature of the lobe carries exactly the energy `target[k]` of the accurate integral
// (interface_albedo). A narrow lobe (small sigma, and the refracted lobe is narrower by about 1 - 1/eta) falls
// between the nodes, and near the normal, where the nodes are sparsest in angle, its node sum errs by percents even
// at N = 6/sigma. Scaling all modes alike keeps the lobe's shape. Columns whose sum or target is 0 are left alone.
void match_column_energy(FourierKernel& kernel, std::span<const double> nodes, std::span<const double> weights,
                         std::span<const double> target);

// The same for a reflection kernel between the nodes themselves (rows and columns over the same |mu_j|, before
// apply_quadrature_weights), keeping its reciprocity: f^m(o, j) -> d_o f^m(o, j) d_j for every mode, with the
// positive d solving  d_j sum_o c_0 a_o |mu_o| f^0(o, j) d_o = target[j]  (a symmetric Sinkhorn-Knopp scaling,
// iterated as d_j <- sqrt(d_j target_j / energy_j(d)) to a relative residual of 1e-12 or 200 steps). A reciprocal
// kernel (f^m(o, j) = f^m(j, o) for reflection inside one medium) stays reciprocal, so the solved BRDF does too.
// Nodes whose column sum or target is 0 keep d = 1.
void match_reflection_energy(FourierKernel& kernel, std::span<const double> nodes, std::span<const double> weights,
                             std::span<const double> target);

// The multiply scattered part of a kernel to outside directions, each column k (along mu_from[k]) scaled to carry
// target[k] exactly: by target[k] / E_k, E_k the lobe's own energy from that direction (MultipleScatteringLobe::energy,
// exact for its interpolant), since the rows are no quadrature. `symmetric`: a reflection between one set of outside
// directions and its mirror (mu_to = -mu_from), whose rows and columns are scaled alike, by sqrt(c_j c_k), which keeps
// it reciprocal; its energy then holds to second order in the scales' spread.
void match_multiple_rows(FourierKernel& multiple, const MultipleScatteringLobe& lobe, std::span<const double> mu_from,
                         bool reflected, std::span<const double> target, bool symmetric = false);
// The same for a kernel already built unmatched (interface_kernel, quadrature weights applied or not), its whole
// kernel with its multiply scattered part, to the reflectances or transmittances of `albedos`' multiple parts.
void match_multiple_rows(InterfaceKernel& kernel, const MultipleScatteringLobe& lobe, std::span<const double> mu_from,
                         bool reflected, std::span<const InterfaceAlbedoParts> albedos, bool symmetric = false);

// Generalized reciprocity of the radiance BTDF (Walter et al. 2007): f_t12(a -> b) / n2^2 = f_t21(b -> a) / n1^2.
// The reversed pair of propagation directions has the same azimuth difference, so for a kernel carrying light from
// medium a into medium b, the kernel from b back into a is its transpose / eta^2, eta = n_b / n_a.
FourierKernel transmission_by_reciprocity(const FourierKernel& a_to_b, double eta);
// Both parts of an InterfaceKernel alike.
InterfaceKernel transmission_by_reciprocity(const InterfaceKernel& a_to_b, double eta);
void apply_quadrature_weights(InterfaceKernel& kernel, std::span<const double> nodes, std::span<const double> weights);

// The accurate albedos (interface_albedo_parts) of an interface for light arriving along each cosine, with the
// direction back toward the light (sin theta, 0, z_sign cos theta) in the interface's frame (+z up): light from above
// has z_sign +1, light from below -1.
std::vector<InterfaceAlbedoParts> interface_albedo_parts_along(const RoughDielectric& interface,
                                                               std::span<const double> cosines, double z_sign,
                                                               const MultipleScatteringLobe* lobe = nullptr);

}  // namespace skinlayer
