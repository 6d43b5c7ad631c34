#include "core/interfaces/interface_operators.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/interface_azimuth_sweep.h"
#include "core/interfaces/multiple_scattering.h"

namespace skinlayer {

namespace {

// Beckmann's D carries exp(-tan^2 theta_h / sigma^2): beyond tan^2 theta_h = 45 sigma^2 it is below e^-45 (3e-20)
// of its peak, and the BSDF with it, whatever the Fresnel, Smith and Jacobian factors (at most ~1e3 there).
constexpr double kNegligibleSlopes2 = 45.0;
// A column (one incident direction) whose lobe comes no nearer to any outgoing direction than tan^2 theta_h =
// 20 sigma^2 falls between them (fewer ordinates than the lobe needs, as in SolveOptions::preview): the energy
// matching (match_column_energy) then scales its far tail up by up to e^20 or more, so the tail is kept whole.
constexpr double kUnresolvedSlopes2 = 20.0;

// The pair (wi, mu_to) of the projection (wi = (-s_i, 0, z_i) as project_propagation_kernel sets it up, wo at
// azimuth phi): the half vector is h ~ wi + b wo, b = 1 for reflection and b = eta_t for transmission
// (microfacet_brdf, microfacet_btdf), so with wo = (s_o cos phi, s_o sin phi, z_o)
//   h_z = z_i + b z_o,   |h_xy|^2 = s_i^2 + b^2 s_o^2 - 2 b s_i s_o cos phi,
// and tan^2 theta_h = |h_xy|^2 / h_z^2 only grows with phi.
struct HalfVectorTilt {
  double base;   // s_i^2 + b^2 s_o^2
  double cross;  // 2 b s_i s_o
  double h_z2;   // h_z^2

  HalfVectorTilt(const RoughDielectric& interface, const Vec3& wi, double mu_to) {
    const double b = wi.z() * mu_to > 0.0 ? 1.0 : (wi.z() > 0.0 ? interface.eta : 1.0 / interface.eta);
    const double s_i = -wi.x();
    const double s_o = std::sqrt(std::max(0.0, 1.0 - mu_to * mu_to));
    const double h_z = wi.z() + b * mu_to;
    base = s_i * s_i + b * b * s_o * s_o;
    cross = 2.0 * b * s_i * s_o;
    h_z2 = h_z * h_z;
  }
  // The least tan^2 theta_h / sigma^2 over the azimuths (phi = 0).
  double least_slopes2(double sigma) const { return (base - cross) / (sigma * sigma * h_z2); }
  // How many leading samples phi_k = k pi / (n - 1) have tan^2 theta_h <= K sigma^2 (one more for rounding).
  int samples_within(double slopes2, double sigma, int n) const {
    const double rest = base - slopes2 * sigma * sigma * h_z2;  // the lobe reaches phi where cross cos phi >= rest
    if (rest <= -cross) return n;
    if (rest > cross) return 0;
    const double widest = std::acos(std::clamp(rest / cross, -1.0, 1.0));
    return std::min(n, static_cast<int>(widest / (kPi / (n - 1))) + 2);
  }
};

// The multiply scattered parts of albedos, reflected or transmitted: what a kernel's lobe is matched to.
std::vector<double> multiple_parts(std::span<const InterfaceAlbedoParts> albedos, bool reflected) {
  std::vector<double> parts;
  for (const InterfaceAlbedoParts& a : albedos)
    parts.push_back(reflected ? a.multiple.reflectance : a.multiple.transmittance);
  return parts;
}

}  // namespace

FourierKernel interface_fourier(const RoughDielectric& interface, std::span<const double> mu_from,
                                std::span<const double> mu_to, const CosineProjector& projector,
                                const CancelCheck& cancelled) {
  const auto kernel_for_pair = [&interface](const Vec3& wi, double cos_to) {
    const double g1_wi = smith_g1_beckmann(wi.z(), interface.sigma);
    const double g1_wo = smith_g1_beckmann(cos_to, interface.sigma);
    return InterfaceAzimuthSweep(interface, wi, cos_to, g1_wi, g1_wo);
  };
  // The azimuths each pair's lobe can reach; grazing pairs, unresolved columns and a missing interface (eta 1, a
  // BSDF of 0) are sampled everywhere.
  const int n = projector.samples();
  const std::size_t n_to = mu_to.size();
  std::vector<int> support(mu_from.size() * n_to, n);
  for (std::size_t a = 0; a < mu_from.size(); ++a) {
    throw_if_cancelled(cancelled);
    const Vec3 wi = -propagation_direction(mu_from[a], 0.0);
    if (interface.eta == 1.0 || wi.z() == 0.0) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < n_to; ++b) {
      if (mu_to[b] == 0.0) continue;
      const HalfVectorTilt tilt(interface, wi, mu_to[b]);
      nearest = std::min(nearest, tilt.least_slopes2(interface.sigma));
      support[a * n_to + b] = tilt.samples_within(kNegligibleSlopes2, interface.sigma, n);
    }
    if (nearest > kUnresolvedSlopes2) std::fill_n(support.begin() + static_cast<std::ptrdiff_t>(a * n_to), n_to, n);
  }
  // Reflection between a set of directions and its mirror (mu_to = -mu_from, as R21 and R23 between the nodes) is
  // reciprocal, f(wi, wo) = f(wo, wi) at the same |Delta phi|, so K^m(b, a) = K^m(a, b): only the pairs b >= a are
  // projected, each with the wider of the two supports, and the rest mirrored.
  const bool mirrored = mu_from.size() == n_to && std::equal(mu_from.begin(), mu_from.end(), mu_to.begin(),
                                                             [](double from, double to) { return to == -from; });
  if (mirrored) {
    for (std::size_t a = 0; a < n_to; ++a) {
      for (std::size_t b = a; b < n_to; ++b) {
        support[a * n_to + b] = std::max(support[a * n_to + b], support[b * n_to + a]);
        if (b > a) support[b * n_to + a] = 0;
      }
    }
  }
  const auto support_for_pair = [&support, n_to](int a, int b) {
    return support[static_cast<std::size_t>(a) * n_to + static_cast<std::size_t>(b)];
  };
  FourierKernel kernel =
      project_propagation_kernel(kernel_for_pair, support_for_pair, mu_from, mu_to, projector, cancelled);
  if (mirrored) {
    for (Eigen::MatrixXd& mode : kernel) {
      for (Eigen::Index a = 0; a < mode.cols(); ++a) {
        for (Eigen::Index b = a + 1; b < mode.rows(); ++b) mode(a, b) = mode(b, a);
      }
    }
  }
  return kernel;
}

FourierKernel multiple_scattering_fourier(const MultipleScatteringLobe& lobe, std::span<const double> mu_from,
                                          std::span<const double> mu_to) {
  FourierKernel result;
  const int modes = lobe.modes();
  const auto rows = static_cast<Eigen::Index>(mu_to.size()), columns = static_cast<Eigen::Index>(mu_from.size());
  // The sets are each of one sign in every use; a mixed set is split by its entries' signs.
  const auto one_sign = [](std::span<const double> mu) {
    return std::all_of(mu.begin(), mu.end(), [&](double v) { return v * mu.front() > 0.0; });
  };
  const bool uniform = !mu_from.empty() && !mu_to.empty() && one_sign(mu_from) && one_sign(mu_to);
  for (int m = 0; m < modes; ++m) {
    const double parity = azimuth_parity(m);
    Eigen::MatrixXd mode = Eigen::MatrixXd::Zero(rows, columns);
    if (uniform) {
      const bool from_above = mu_from.front() < 0.0;  // travelling down: arriving from above
      const bool reflected = mu_from.front() * mu_to.front() < 0.0;
      mode = parity * (reflected ? lobe.reflection_modes(from_above, m, mu_from, mu_to)
                                 : lobe.transmission_modes(from_above, m, mu_from, mu_to))
                          .transpose();
    } else {
      for (Eigen::Index a = 0; a < columns; ++a) {
        const double from = mu_from[static_cast<std::size_t>(a)];
        for (Eigen::Index b = 0; b < rows; ++b) {
          const double to = mu_to[static_cast<std::size_t>(b)];
          if (from == 0.0 || to == 0.0) continue;
          mode(b, a) = parity * (from * to < 0.0 ? lobe.reflection(from < 0.0, m, std::abs(from), std::abs(to))
                                                 : lobe.transmission(from < 0.0, m, std::abs(from), std::abs(to)));
        }
      }
    }
    result.push_back(std::move(mode));
  }
  return result;
}

Eigen::MatrixXd InterfaceKernel::single_scattering(int m) const {
  const Eigen::MatrixXd& mode = kernel[static_cast<std::size_t>(m)];
  return has_multiple(m) ? Eigen::MatrixXd(mode - multiple[static_cast<std::size_t>(m)]) : mode;
}

const Eigen::MatrixXd* InterfaceKernel::carried_by_tables(int m, bool exact) const {
  return exact ? nullptr : &kernel[static_cast<std::size_t>(m)];
}

std::size_t InterfaceKernel::bytes() const { return fourier_kernel_bytes(kernel) + fourier_kernel_bytes(multiple); }

InterfaceKernel matched_interface_kernel(const RoughDielectric& interface, std::span<const double> mu_from,
                                         std::span<const double> mu_to, const CosineProjector& projector,
                                         EnergyMatch match, std::span<const InterfaceAlbedoParts> albedos,
                                         std::span<const double> nodes, std::span<const double> weights,
                                         const CancelCheck& cancelled, const MultipleScatteringLobe* lobe_given) {
  InterfaceKernel result{interface_fourier(interface, mu_from, mu_to, projector, cancelled), {}};
  std::optional<MultipleScatteringLobe> own;
  if (lobe_given == nullptr && has_multiple_scattering(interface)) own.emplace(interface, projector.modes());
  const MultipleScatteringLobe* multiple_lobe = lobe_given != nullptr ? lobe_given : (own ? &*own : nullptr);
  FourierKernel lobe;
  if (multiple_lobe != nullptr && has_multiple_scattering(interface)) {
    lobe = multiple_scattering_fourier(*multiple_lobe, mu_from, mu_to);
  }
  const bool multiple = !lobe.empty();
  const bool rows = match == EnergyMatch::ReflectedRows || match == EnergyMatch::TransmittedRows;
  if (rows && multiple) {
    const bool reflected = match == EnergyMatch::ReflectedRows;
    match_multiple_rows(lobe, *multiple_lobe, mu_from, reflected, multiple_parts(albedos, reflected));
  } else if (match != EnergyMatch::None && !rows) {
    const bool reflected = match != EnergyMatch::TransmittedColumns;
    std::vector<double> single;
    for (const InterfaceAlbedoParts& a : albedos)
      single.push_back(reflected ? a.single.reflectance : a.single.transmittance);
    const std::vector<double> rest = multiple_parts(albedos, reflected);
    const auto matched = [&](FourierKernel& kernel, const std::vector<double>& target) {
      if (match == EnergyMatch::Reflection) {
        match_reflection_energy(kernel, nodes, weights, target);
      } else {
        match_column_energy(kernel, nodes, weights, target);
      }
    };
    matched(result.kernel, single);
    if (multiple) {
      // The lobe is interpolated from its table, whose losses are too: where single scattering loses nothing here,
      // the lobe carries nothing either (a reflection's row with its column, to stay symmetric).
      for (std::size_t k = 0; k < rest.size(); ++k) {
        if (rest[k] > 0.0) continue;
        const auto column = static_cast<Eigen::Index>(k);
        for (Eigen::MatrixXd& mode : lobe) {
          mode.col(column).setZero();
          if (match == EnergyMatch::Reflection) mode.row(column).setZero();
        }
      }
      matched(lobe, rest);
    }
  }
  if (multiple) {
    for (std::size_t m = 0; m < lobe.size(); ++m) result.kernel[m] += lobe[m];
    result.multiple = std::move(lobe);
  }
  return result;
}

InterfaceKernel interface_kernel(const RoughDielectric& interface, std::span<const double> mu_from,
                                 std::span<const double> mu_to, const CosineProjector& projector,
                                 const CancelCheck& cancelled, const MultipleScatteringLobe* lobe) {
  return matched_interface_kernel(interface, mu_from, mu_to, projector, EnergyMatch::None, {}, {}, {}, cancelled, lobe);
}

void apply_quadrature_weights(InterfaceKernel& kernel, std::span<const double> nodes, std::span<const double> weights) {
  apply_quadrature_weights(kernel.kernel, nodes, weights);
  apply_quadrature_weights(kernel.multiple, nodes, weights);
}

InterfaceKernel transmission_by_reciprocity(const InterfaceKernel& a_to_b, double eta) {
  InterfaceKernel b_to_a{transmission_by_reciprocity(a_to_b.kernel, eta), {}};
  b_to_a.multiple = transmission_by_reciprocity(a_to_b.multiple, eta);
  return b_to_a;
}

void apply_quadrature_weights(FourierKernel& kernel, std::span<const double> nodes, std::span<const double> weights) {
  for (std::size_t m = 0; m < kernel.size(); ++m) {
    const double c_m = fourier_azimuth_weight(static_cast<int>(m));
    for (Eigen::Index j = 0; j < kernel[m].cols(); ++j) {
      kernel[m].col(j) *= c_m * std::abs(nodes[j]) * weights[j];
    }
  }
}

void match_column_energy(FourierKernel& kernel, std::span<const double> nodes, std::span<const double> weights,
                         std::span<const double> target) {
  if (kernel.empty()) return;
  for (Eigen::Index k = 0; k < kernel[0].cols(); ++k) {
    double quadrature = 0.0;
    for (Eigen::Index j = 0; j < kernel[0].rows(); ++j) {
      quadrature += fourier_azimuth_weight(0) * weights[j] * std::abs(nodes[j]) * kernel[0](j, k);
    }
    const double wanted = target[static_cast<std::size_t>(k)];
    if (quadrature <= 0.0 || wanted <= 0.0) continue;
    for (Eigen::MatrixXd& mode : kernel) mode.col(k) *= wanted / quadrature;
  }
}

void match_reflection_energy(FourierKernel& kernel, std::span<const double> nodes, std::span<const double> weights,
                             std::span<const double> target) {
  constexpr int kMaxSteps = 200;
  constexpr double kTolerance = 1e-12;
  if (kernel.empty()) return;
  const Eigen::Index n = kernel[0].cols();
  Eigen::VectorXd row_weight(n);  // c_0 a_o |mu_o|
  for (Eigen::Index o = 0; o < n; ++o) row_weight(o) = fourier_azimuth_weight(0) * weights[o] * std::abs(nodes[o]);
  const Eigen::Map<const Eigen::VectorXd> wanted(target.data(), n);
  const Eigen::MatrixXd weighted = row_weight.asDiagonal() * kernel[0];
  const Eigen::Array<bool, Eigen::Dynamic, 1> active =
      (wanted.array() > 0.0) && ((weighted.colwise().sum().transpose().array()) > 0.0);
  Eigen::VectorXd d = Eigen::VectorXd::Ones(n);
  for (int step = 0; step < kMaxSteps; ++step) {
    const Eigen::VectorXd energy = d.cwiseProduct(weighted.transpose() * d);  // energy_j = d_j sum_o w_o f(o,j) d_o
    double residual = 0.0;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (!active(j)) continue;
      residual = std::max(residual, std::abs(energy(j) / wanted(j) - 1.0));
      d(j) *= std::sqrt(wanted(j) / energy(j));
    }
    if (residual < kTolerance) break;
  }
  for (Eigen::MatrixXd& mode : kernel) mode = d.asDiagonal() * mode * d.asDiagonal();
}

void match_multiple_rows(FourierKernel& multiple, const MultipleScatteringLobe& lobe, std::span<const double> mu_from,
                         bool reflected, std::span<const double> target, bool symmetric) {
  if (multiple.empty()) return;
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(static_cast<Eigen::Index>(mu_from.size()));
  for (std::size_t k = 0; k < mu_from.size(); ++k) {
    const double carried = lobe.energy(mu_from[k] < 0.0, reflected, std::abs(mu_from[k]));
    if (carried > 0.0) scale(static_cast<Eigen::Index>(k)) = std::max(target[k], 0.0) / carried;
  }
  if (symmetric) {
    const Eigen::VectorXd root = scale.cwiseSqrt();
    for (Eigen::MatrixXd& mode : multiple) mode = root.asDiagonal() * mode * root.asDiagonal();
  } else {
    for (Eigen::MatrixXd& mode : multiple) mode = mode * scale.asDiagonal();
  }
}

void match_multiple_rows(InterfaceKernel& kernel, const MultipleScatteringLobe& lobe, std::span<const double> mu_from,
                         bool reflected, std::span<const InterfaceAlbedoParts> albedos, bool symmetric) {
  if (!kernel.has_multiple()) return;
  FourierKernel matched = kernel.multiple;
  match_multiple_rows(matched, lobe, mu_from, reflected, multiple_parts(albedos, reflected), symmetric);
  for (std::size_t m = 0; m < matched.size(); ++m) {
    kernel.kernel[m] += matched[m] - kernel.multiple[m];
    kernel.multiple[m] = std::move(matched[m]);
  }
}

FourierKernel transmission_by_reciprocity(const FourierKernel& a_to_b, double eta) {
  FourierKernel b_to_a(a_to_b.size());
  for (std::size_t m = 0; m < a_to_b.size(); ++m) b_to_a[m] = a_to_b[m].transpose() / (eta * eta);
  return b_to_a;
}

std::vector<InterfaceAlbedoParts> interface_albedo_parts_along(const RoughDielectric& interface,
                                                               std::span<const double> cosines, double z_sign,
                                                               const MultipleScatteringLobe* lobe) {
  std::vector<Vec3> toward_light;
  toward_light.reserve(cosines.size());
  for (const double mu : cosines) {
    toward_light.emplace_back(std::sqrt(std::max(0.0, 1.0 - mu * mu)), 0.0, z_sign * std::abs(mu));
  }
  return interface_albedo_parts(interface, toward_light, lobe);
}

}  // namespace skinlayer
