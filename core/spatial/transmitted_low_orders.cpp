// docs/model.md §21.15: the unscattered and once-scattered light out of a finite stack's bottom, continuous in angle.
#include "core/spatial/transmitted_low_orders.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <vector>

#include "core/conventions.h"
#include "core/medium/henyey_greenstein.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

// The depths of a stack whose slabs must all be finite (stack_depths).
StackDepths finite_stack_depths(std::span<const LateralSlab> slabs) {
  if (slabs.empty()) throw std::invalid_argument("transmitted light: needs at least one slab");
  for (const LateralSlab& s : slabs) {
    if (!(s.tau >= 0.0 && std::isfinite(s.tau)) || !(s.albedo >= 0.0 && s.albedo <= 1.0) || !(std::abs(s.g) <= 0.95) ||
        !(s.relative_extinction > 0.0 && std::isfinite(s.relative_extinction))) {
      throw std::invalid_argument(
          "transmitted light: finite tau >= 0, albedo in [0, 1], g in [-0.95, 0.95] and a finite relative extinction "
          "> 0");
    }
  }
  return stack_depths(slabs);
}

double exit_fraction(const ExitFraction& exit, double mu) { return exit ? exit(mu) : 1.0; }

// int_lo^hi e^{-rate (z - ref)} dz, where rate (z - ref) >= 0 on [lo, hi].
double exponential_integral(double rate, double ref, double lo, double hi) {
  const double x = rate * (hi - lo);
  if (std::abs(x) < 1.0) return std::exp(-rate * (lo - ref)) * (x == 0.0 ? hi - lo : -std::expm1(-x) / rate);
  return (std::exp(-rate * (lo - ref)) - std::exp(-rate * (hi - ref))) / rate;
}

// The place of the exit point: r(z)^2 = q(z) = d2 z^2 + 2 h z + c, with d2 = |A - B|^2, h = H B.(A - B), c = H^2 |B|^2.
struct Displacement {
  double d2, h, c;
  // The part of [lo, hi] where q(z) < v: an interval, (lo, lo) when empty.
  std::pair<double, double> below(double v, double lo, double hi) const {
    const double scale = c + std::abs(h) * hi + d2 * hi * hi;
    if (d2 * hi * hi <= 1e-13 * scale) {  // q linear in z: 2 h z + c
      if (h == 0.0) return c < v ? std::pair{lo, hi} : std::pair{lo, lo};
      const double cut = (v - c) / (2.0 * h);
      return h > 0.0 ? std::pair{lo, std::clamp(cut, lo, hi)} : std::pair{std::clamp(cut, lo, hi), hi};
    }
    const double discriminant = h * h - d2 * (c - v);
    if (discriminant <= 0.0) return {lo, lo};
    const double root = std::sqrt(discriminant);
    const double z0 = (-h - root) / d2, z1 = (-h + root) / d2;
    const double from = std::clamp(z0, lo, hi), to = std::clamp(z1, lo, hi);
    return from < to ? std::pair{from, to} : std::pair{lo, lo};
  }
  // The roots of q(z) = v in [lo, hi], with sqrt of the discriminant (|dq/dz| / 2 there).
  template <class Visit>
  void roots(double v, double lo, double hi, const Visit& visit) const {
    const double scale = c + std::abs(h) * hi + d2 * hi * hi;
    if (d2 * hi * hi <= 1e-13 * scale) {
      if (h == 0.0) return;
      const double z = (v - c) / (2.0 * h);
      if (z >= lo && z < hi) visit(z, std::abs(h));
      return;
    }
    const double discriminant = h * h - d2 * (c - v);
    if (discriminant <= 0.0) return;
    const double root = std::sqrt(discriminant);
    for (const double z : {(-h - root) / d2, (-h + root) / d2}) {
      if (z >= lo && z < hi) visit(z, root);
    }
  }
};

// sum over entering directions e, slabs l, leaving directions o and azimuths of the path's weight times
// along(rate, ref, z_lo, z_hi, displacement): the z-integral of e^{-rate (z - ref)} over the slab's part that falls in
// the annulus or, for a density, the roots' sum. ref is the slab's top where the path's weight falls with depth, else
// its bottom, so that no exponential overflows.
// The leaving directions' panels also break at atan(r / H) for each radius r that bounds the annulus (or is the
// density's): there a path scattered straight below the entry point starts or stops reaching it, an edge in theta_o.
template <class Along>
double over_scattering_paths(std::span<const LateralSlab> slabs, const EnteringRadiance& entering,
                             const ExitFraction& exit, std::initializer_list<double> radii, const Along& along) {
  const StackDepths depths = finite_stack_depths(slabs);
  const double H = depths.height;
  std::vector<std::pair<double, double>> panels;
  std::vector<double> breaks = {0.0, 0.5 * kPi};
  for (const double r : radii) {
    if (r > 0.0 && std::isfinite(r)) breaks.push_back(std::atan2(r, H));
  }
  std::sort(breaks.begin(), breaks.end());
  for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
    if (breaks[b + 1] <= breaks[b]) continue;
    for (const auto& panel : graded_panels(breaks[b], breaks[b + 1], b == 0 ? 0.1 : 0.0, 0.1)) panels.push_back(panel);
  }
  const QuadratureRule leaving = gauss_legendre_panels(panels, 6);
  // The azimuth between entering and leaving on [0, pi] (doubled: the integrand is even), closer where forward
  // scattering peaks.
  static const QuadratureRule azimuths = gauss_legendre_panels(
      std::array{std::pair{0.0, 0.15 * kPi}, std::pair{0.15 * kPi, 0.5 * kPi}, std::pair{0.5 * kPi, kPi}}, 16);
  // The collimated beam first (mu_e = 1), then the entering radiance's directions.
  std::vector<double> entry_mu = {1.0}, entry_power = {entering.collimated()};
  const QuadratureRule& radiance = entering.directions();
  entry_mu.insert(entry_mu.end(), radiance.nodes.begin(), radiance.nodes.end());
  entry_power.insert(entry_power.end(), radiance.weights.begin(), radiance.weights.end());
  double total = 0.0;
  for (std::size_t e = 0; e < entry_mu.size(); ++e) {
    if (entry_power[e] <= 0.0) continue;
    const double mu_e = entry_mu[e], sin_e = std::sqrt(std::max(0.0, 1.0 - mu_e * mu_e)), a = sin_e / mu_e;
    const bool vertical = sin_e == 0.0;
    for (std::size_t l = 0; l < slabs.size(); ++l) {
      const LateralSlab& slab = slabs[l];
      if (slab.tau == 0.0 || slab.albedo == 0.0) continue;
      const double e_l = slab.relative_extinction;
      const double z_top = depths.geometric[l], z_bottom = z_top + slab.tau / e_l;
      for (std::size_t o = 0; o < leaving.nodes.size(); ++o) {
        const double theta_o = leaving.nodes[o], mu_o = std::cos(theta_o), sin_o = std::sin(theta_o);
        const double b = sin_o / mu_o;
        const double rate = e_l * (1.0 / mu_e - 1.0 / mu_o);
        const bool falls = rate >= 0.0;
        const double ref = falls ? z_top : z_bottom;
        const double optical_ref = depths.optical[l] + (falls ? 0.0 : slab.tau);
        const double weight = entry_power[e] * slab.albedo * e_l / mu_e * exit_fraction(exit, mu_o) *
                              std::exp(-optical_ref / mu_e - (depths.tau - optical_ref) / mu_o) * leaving.weights[o] *
                              sin_o;
        if (weight == 0.0) continue;
        if (vertical) {
          const Displacement r{b * b, -H * b * b, H * H * b * b};
          total += weight * 2.0 * kPi * henyey_greenstein(mu_o, slab.g) * along(rate, ref, z_top, z_bottom, r);
          continue;
        }
        for (std::size_t p = 0; p < azimuths.nodes.size(); ++p) {
          const double c = std::cos(azimuths.nodes[p]);
          const Displacement r{a * a + b * b - 2.0 * a * b * c, H * (a * b * c - b * b), H * H * b * b};
          total += weight * 2.0 * azimuths.weights[p] * henyey_greenstein(mu_e * mu_o + sin_e * sin_o * c, slab.g) *
                   along(rate, ref, z_top, z_bottom, r);
        }
      }
    }
  }
  return total;
}

// Gauss-Legendre panels over [theta0, theta1), narrower than a quarter of the entering lobe.
template <class Integrand>
double over_polar_angle(const EnteringRadiance& entering, double theta0, double theta1, const Integrand& f) {
  const double widest = entering.lobe_width() > 0.0 ? std::min(0.02, 0.25 * entering.lobe_width()) : 0.02;
  static const QuadratureRule unit = gauss_legendre(8, 0.0, 1.0);
  const int panels = std::max(1, static_cast<int>(std::ceil((theta1 - theta0) / widest)));
  double total = 0.0;
  for (int p = 0; p < panels; ++p) {
    total += integrate_mapped(unit, theta0 + (theta1 - theta0) * p / panels,
                              theta0 + (theta1 - theta0) * (p + 1) / panels, f);
  }
  return total;
}

void check_annulus(double r0, double r1) {
  if (!(r0 >= 0.0 && r1 >= r0)) throw std::invalid_argument("transmitted light: needs 0 <= r0 <= r1");
}

}  // namespace

double unscattered_transmitted_power(std::span<const LateralSlab> slabs, const EnteringRadiance& entering,
                                     const ExitFraction& exit, double r0, double r1) {
  check_annulus(r0, r1);
  const StackDepths depths = finite_stack_depths(slabs);
  if (entering.directions().nodes.empty() || r1 == r0) return 0.0;
  const double theta0 = std::atan2(r0, depths.height), theta1 = std::atan2(r1, depths.height);
  return over_polar_angle(entering, theta0, theta1, [&](double theta) {
    const double mu = std::cos(theta);
    if (mu <= 0.0) return 0.0;
    return 2.0 * kPi * entering(mu) * exit_fraction(exit, mu) * std::exp(-depths.tau / mu) * mu * std::sin(theta);
  });
}

double unscattered_transmitted_density(std::span<const LateralSlab> slabs, const EnteringRadiance& entering,
                                       const ExitFraction& exit, double r) {
  if (!(r > 0.0 && std::isfinite(r))) throw std::invalid_argument("transmitted light: r must be finite and > 0");
  const StackDepths depths = finite_stack_depths(slabs);
  if (entering.directions().nodes.empty()) return 0.0;
  const double H = depths.height, mu = H / std::hypot(H, r);
  return entering(mu) * exit_fraction(exit, mu) * std::exp(-depths.tau / mu) * std::pow(mu, 4) / (H * H);
}

double single_scattered_transmitted_power(std::span<const LateralSlab> slabs, const EnteringRadiance& entering,
                                          const ExitFraction& exit, double r0, double r1) {
  check_annulus(r0, r1);
  return over_scattering_paths(slabs, entering, exit, {r0, r1},
                               [&](double rate, double ref, double lo, double hi, const Displacement& r) {
                                 const auto [u1, v1] = r.below(r1 * r1, lo, hi);
                                 if (!(v1 > u1)) return 0.0;
                                 const auto [u0, v0] = r0 > 0.0 ? r.below(r0 * r0, lo, hi) : std::pair{lo, lo};
                                 if (!(v0 > u0)) return exponential_integral(rate, ref, u1, v1);
                                 double sum = 0.0;
                                 if (std::min(v1, u0) > u1)
                                   sum += exponential_integral(rate, ref, u1, std::min(v1, u0));
                                 if (v1 > std::max(u1, v0))
                                   sum += exponential_integral(rate, ref, std::max(u1, v0), v1);
                                 return sum;
                               });
}

double single_scattered_transmitted_density(std::span<const LateralSlab> slabs, const EnteringRadiance& entering,
                                            const ExitFraction& exit, double r) {
  if (!(r > 0.0 && std::isfinite(r))) throw std::invalid_argument("transmitted light: r must be finite and > 0");
  return over_scattering_paths(slabs, entering, exit, {r},
                               [&](double rate, double ref, double lo, double hi, const Displacement& d) {
                                 double sum = 0.0;
                                 d.roots(r * r, lo, hi, [&](double z, double half_slope) {
                                   sum += std::exp(-rate * (z - ref)) / half_slope;
                                 });
                                 return sum;
                               }) /
         (2.0 * kPi);
}

}  // namespace skinlayer
