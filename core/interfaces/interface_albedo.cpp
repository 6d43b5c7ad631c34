#include "core/interfaces/interface_albedo.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/interfaces/multiple_scattering.h"
#include "core/interfaces/transmission_masking_table.h"
#include "core/series/quadrature.h"

namespace skinlayer {
namespace {

// The exact Smith G1 (microfacet.h) of one sigma, tabulated at 4097 cosines uniform in [0, 1] and read back by
// Catmull-Rom interpolation (third order; G1 bends over dc ~ sigma): against smith_g1_beckmann at 2e6 cosines, at
// most 3.4e-7 at sigma 0.05, 5e-9 at 0.2, 5e-11 at 1. Two G1 per slope sample were 2/3 of the integration's cost
// (erf and exp, ~20 ns each).
class SmithG1Table {
 public:
  explicit SmithG1Table(double sigma) : values_(kSize + 2) {
    for (int i = 0; i < kSize; ++i) values_[i + 1] = smith_g1_beckmann(static_cast<double>(i) / (kSize - 1), sigma);
    // A ghost node below c = 0 by quadratic extrapolation (G1 = 2 sqrt(pi) a (1 - sqrt(pi) a + ...), a = c / sigma,
    // is not odd: an odd extension erred by 2e-5 in the first interval at sigma 0.05).
    values_[0] = 3.0 * values_[1] - 3.0 * values_[2] + values_[3];
    values_[kSize + 1] = 1.0;  // G1 = 1 near c = 1
  }
  double operator()(double cos_theta) const {
    const double x = std::min(std::abs(cos_theta), 1.0) * (kSize - 1);
    const int i = std::min(static_cast<int>(x), kSize - 2);
    const double t = x - i;
    const double* v = &values_[i];  // G1 at nodes i-1, i, i+1, i+2
    return v[1] + 0.5 * t *
                      (v[2] - v[0] +
                       t * (2.0 * v[0] - 5.0 * v[1] + 4.0 * v[2] - v[3] + t * (3.0 * (v[1] - v[2]) + v[3] - v[0])));
  }

 private:
  static constexpr int kSize = 4097;
  std::vector<double> values_;
};

// A point where the integrand is not smooth: a kink, or (singular) a square-root edge, where the Fresnel
// transmission 1 - F ~ sqrt(cos_i - cos_critical) vanishes at total internal reflection.
struct Breakpoint {
  double x;
  bool singular;
};

// int f(x) dx over the pieces between sorted breakpoints, n-point Gauss-Legendre on each piece. A piece nearer to a
// singular breakpoint s than its own length is integrated in u = sqrt(|x - s|) (x = s +- u^2, dx = 2u du), which
// turns sqrt(x - s) g(x) + h(x) into the smooth u g + h; with such points near both ends the piece is halved and
// each half is mapped from its nearer one.
// rule_for(a, b) gives the Gauss-Legendre rule on [0, 1] for the piece [a, b], or nullptr where it holds nothing.
template <class Value, class RuleFor, class Integrand>
Value integrate_pieces(std::vector<Breakpoint>& points, RuleFor&& rule_for, Integrand&& f) {
  std::sort(points.begin(), points.end(), [](const Breakpoint& a, const Breakpoint& b) { return a.x < b.x; });
  std::array<double, 8> singular_points{};  // at most two cone roots in a row, five edges across rows
  std::size_t singular_count = 0;
  for (const Breakpoint& point : points)
    if (point.singular && singular_count < singular_points.size()) singular_points[singular_count++] = point.x;
  const std::span<const double> singular(singular_points.data(), singular_count);
  Value sum{};
  const QuadratureRule* rule = nullptr;
  const auto gauss = [&](double u0, double u1, auto&& x_of_u, auto&& jacobian) {
    const QuadratureRule& unit_rule = *rule;
    for (int k = 0; k < unit_rule.size(); ++k) {
      const double u = u0 + (u1 - u0) * unit_rule.nodes[k];
      sum += f(x_of_u(u)) * (unit_rule.weights[k] * (u1 - u0) * jacobian(u));
    }
  };
  const auto piece = [&](double a, double b, double left, double right) {  // nearest singular points outside
    rule = rule_for(a, b);
    if (rule == nullptr) return;
    const double length = b - a;
    const bool near_left = a - left < length, near_right = right - b < length;
    if (near_left && (!near_right || a - left <= right - b)) {
      gauss(
          std::sqrt(a - left), std::sqrt(b - left), [&](double u) { return left + u * u; },
          [](double u) { return 2.0 * u; });
    } else if (near_right) {
      gauss(
          std::sqrt(right - b), std::sqrt(right - a), [&](double u) { return right - u * u; },
          [](double u) { return 2.0 * u; });
    } else {
      gauss(
          a, b, [](double x) { return x; }, [](double) { return 1.0; });
    }
  };
  const double infinity = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double a = points[i].x, b = points[i + 1].x;
    if (!(b > a)) continue;
    const auto above = std::lower_bound(singular.begin(), singular.end(), b);
    const auto below = std::upper_bound(singular.begin(), singular.end(), a);
    const double left = below == singular.begin() ? -infinity : *(below - 1);
    const double right = above == singular.end() ? infinity : *above;
    if (a - left < b - a && right - b < b - a) {
      const double middle = 0.5 * (a + b);
      piece(a, middle, left, right);
      piece(middle, b, left, right);
    } else {
      piece(a, b, left, right);
    }
  }
  return sum;
}

// Adds the real roots of a x^2 + b x + c = 0 that lie in (lo, hi).
void add_quadratic_roots(double a, double b, double c, double lo, double hi, bool singular,
                         std::vector<Breakpoint>& points) {
  const auto add = [&](double x) {
    if (x > lo && x < hi) points.push_back({x, singular});
  };
  if (std::abs(a) < 1e-14 * (std::abs(b) + std::abs(c))) {
    if (b != 0.0) add(-c / b);
    return;
  }
  const double discriminant = b * b - 4.0 * a * c;
  if (discriminant < 0.0) return;
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));  // no cancellation (Numerical Recipes 5.6)
  if (q == 0.0) {
    add(0.0);
    return;
  }
  add(q / a);
  add(c / q);
}

struct AlbedoPair {
  double reflectance = 0.0;
  double transmittance = 0.0;
  AlbedoPair& operator+=(const AlbedoPair& o) {
    reflectance += o.reflectance;
    transmittance += o.transmittance;
    return *this;
  }
  AlbedoPair operator*(double w) const { return {reflectance * w, transmittance * w}; }
};

// Gauss-Legendre rules on [0, 1] by the weight a piece can carry: a piece whose Gaussian slope density is at most w
// (relative to the peak) needs only the relative accuracy ~1e-7 / w, so the rules shrink from 8 points where the
// density is within 1/50 of its peak to 2 in the far tail, and pieces below 1e-12 are skipped. Pieces are at most
// sigma wide and cover |p|, |q| <= 5.5 sigma. Measured against 16-point rules on half-sigma pieces and against
// adaptive Gauss-Kronrod: worst 4.6e-7 over sigma 0.05-1, eta 1.05-2, both sides, 0-89 degrees.
//
// Those are the single-scattering model's rules, where R and T are the interface's whole albedo and what they miss
// is lost light; they stay as they are, so that Stam's model reproduces its numbers bit for bit. Under the
// multiple-scattering model the integrals only split the light between the specular lobe and the multiply scattered
// one (l = 1 - R - T takes whatever they miss, so R + T + l = 1 exactly), and that split is known only to the lobe
// table's ~3e-3 (the random walk's). There the rules are one size smaller (6, 4, 2 and 2 points, pieces below 1e-10
// skipped): worst 2.1e-5 against the single model's rules over sigma 0.05-1, eta 1.05-2.5, both sides, 0-89
// degrees (at sigma 1, eta 2.5, from below at 68 degrees), for 30% less of the solve's largest cost.
//
// A row, or the range of rows, that no kink crosses is integrated instead by one Gauss-Hermite rule in x = p / sigma
// (its weights carry e^{x^2} back out, since the integrand includes the density) when sigma <= 0.5: the geometric
// factors (s = sqrt(1 + p^2 + q^2) and what follows from it) are analytic within ~1 of the real slopes, >= 2 sigma,
// where 20 points converge to ~1e-11 (at sigma 1 they leave 2e-5).
class PieceRules {
 public:
  static constexpr double kHermiteMaxSigma = 0.5;

  explicit PieceRules(MicrofacetModel model)
      : tiers_(model == MicrofacetModel::Single ? kSingleTiers : kSplitTiers),
        rules_{gauss_legendre(tiers_[0].nodes, 0.0, 1.0), gauss_legendre(tiers_[1].nodes, 0.0, 1.0),
               gauss_legendre(tiers_[2].nodes, 0.0, 1.0), gauss_legendre(tiers_[3].nodes, 0.0, 1.0)},
        hermite_(gauss_hermite(kHermiteNodes)) {
    for (int k = 0; k < hermite_.size(); ++k) hermite_.weights[k] *= std::exp(hermite_.nodes[k] * hermite_.nodes[k]);
  }
  // int_R f(x) dx ~ sum_k w_k f(x_k) for f = e^{-x^2} times a smooth function.
  const QuadratureRule& hermite() const { return hermite_; }
  // The rule for a piece whose largest relative density is `density`; nullptr when it holds nothing.
  const QuadratureRule* operator()(double density) const {
    for (std::size_t t = 0; t < tiers_.size(); ++t)
      if (density >= tiers_[t].density) return &rules_[t];
    return nullptr;
  }

 private:
  struct Tier {
    double density;
    int nodes;
  };
  using Tiers = std::array<Tier, 4>;
  static constexpr Tiers kSingleTiers{{{0.02, 8}, {1e-4, 6}, {1e-7, 4}, {1e-12, 2}}};
  static constexpr Tiers kSplitTiers{{{0.02, 6}, {1e-4, 4}, {1e-7, 2}, {1e-10, 2}}};
  static constexpr int kHermiteNodes = 20;  // even: no node at 0, so the positive half serves a half-range
  Tiers tiers_;
  std::array<QuadratureRule, 4> rules_;
  QuadratureRule hermite_;
};

constexpr double kPieceWidth = 1.0;  // in sigma
constexpr double kSlopeRange = 5.5;  // in sigma: the density beyond holds erfc(5.5) = 7e-15

// The integration for light arriving along wi, with wi rotated into the xz-plane on the +z side:
// wi = (sx, 0, wz), relative index e = n_transmitted / n_incident. Slopes (p, q) give the microfacet normal
// h = (-p, -q, 1) / s with s = sqrt(1 + p^2 + q^2), and then (Walter et al. 2007, eqs. 14 and 17)
//   R = int F(wi.h) G1(wi) G1(wo_r) (wi.h) / (wz h_z) P(p, q) dp dq,  T likewise with (1 - F) and wo_t,
// where P = exp(-(p^2+q^2)/sigma^2) / (pi sigma^2) is the Beckmann slope density and (wi.h)/h_z = wz - p sx.
// The integrand's kinks in slope space are all conics, found in closed form row by row (fixed q):
//   wi.h = 0 (the facet turns its back to wi):   the line p = wz / sx;
//   wo_r on the horizon, h ~ wi + (cos phi, sin phi, 0):   the circle centred (-sx/wz, 0) of radius 1/wz;
//   wo_t on the horizon, h ~ wi + e (cos phi, sin phi, 0): the circle centred (-sx/wz, 0) of radius e/wz;
//   total internal reflection (e < 1), wi.h = c = sqrt(1 - e^2): the cone (wz - p sx)^2 = c^2 (1 + p^2 + q^2),
//   a square-root edge of 1 - F.
// Each row is integrated piecewise between them (integrate_pieces); the rows' integral is kinked where a conic's
// pair of roots appears (q = 1/wz, e/wz, and e / sqrt(c^2 - sx^2) for the cone), so the q range is split there too.
AlbedoPair integrate_slopes(double sx, double wz, double e, double sigma, double g1_in, MicrofacetModel microfacet,
                            const SmithG1Table& smith_g1, const PieceRules& rules) {
  const double range = kSlopeRange * sigma;
  const double step = kPieceWidth * sigma;
  const double sigma2 = sigma * sigma;
  const double critical = e < 1.0 ? std::sqrt(1.0 - e * e) : 0.0;  // cos of the critical angle at a facet
  const double centre = -sx / wz;
  const double normalization = 2.0 * g1_in / (wz * kPi * sigma2);  // 2: the q < 0 half mirrors the q > 0 half
  // The masking-shadowing G2(wi, wo) / G1(wi) (G1(wi) is in the normalization): G1(wo) in the separable form; the
  // height-correlated form (smith_masking.h) in reflection as g_o / (g_i + g_o - g_i g_o), one division, and in
  // transmission from the table's row at this g_i (transmission_masking_table.h).
  const TransmissionMaskingRow transmission_masking(microfacet == MicrofacetModel::Multiple ? g1_in : 0.0);
  const auto outgoing_masking = [g1_in, microfacet, &transmission_masking](double g1_out, bool transmitted) {
    if (microfacet == MicrofacetModel::Single) return g1_out;
    if (transmitted) return transmission_masking(g1_out) / g1_in;
    return g1_out / (g1_in + g1_out * (1.0 - g1_in));
  };

  // The largest relative density exp(-x^2 / sigma^2) over [a, b].
  const auto peak_density = [&](double a, double b) {
    const double nearest = a > 0.0 ? a : (b < 0.0 ? -b : 0.0);
    return std::exp(-nearest * nearest / sigma2);
  };
  const bool smooth_enough = sigma <= PieceRules::kHermiteMaxSigma;  // for Gauss-Hermite where no kink is near
  const double back_facing = sx > 0.0 ? wz / sx : std::numeric_limits<double>::infinity();  // wi.h <= 0 beyond

  const auto uniform_breakpoints = [&](double lo, std::vector<Breakpoint>& points) {
    for (double x = lo; x < range; x += step) points.push_back({x, false});
    points.push_back({range, false});
  };

  std::vector<Breakpoint> points;  // one row's, reused
  const auto row = [&](double q) {
    points.clear();
    uniform_breakpoints(-range, points);
    const std::size_t uniform_count = points.size();
    if (back_facing < range) points.push_back({back_facing, false});
    for (double radius : {1.0 / wz, e / wz}) {
      if (radius > 1.0 / wz) continue;  // e > 1: the refracted ray always goes down (no transmission horizon)
      const double half_chord2 = radius * radius - q * q;
      if (half_chord2 > 0.0) {
        const double half_chord = std::sqrt(half_chord2);
        for (double p : {centre - half_chord, centre + half_chord})
          if (std::abs(p) < range) points.push_back({p, false});
      }
    }
    if (e < 1.0) {
      const double c2 = critical * critical;
      add_quadratic_roots(sx * sx - c2, -2.0 * wz * sx, wz * wz - c2 * (1.0 + q * q), -range, range, true, points);
    }
    const double row_density = std::exp(-q * q / sigma2);
    const auto rule_for = [&](double a, double b) {
      return a >= back_facing ? nullptr : rules(row_density * peak_density(a, b));
    };
    const auto integrand = [&](double p) -> AlbedoPair {
      const double along = wz - p * sx;  // s (wi.h)
      if (along <= 0.0) return {};
      const double s = std::sqrt(1.0 + p * p + q * q);
      const double cos_i = along / s;
      const double common = along * row_density * std::exp(-p * p / sigma2);
      const auto [fresnel, cos_t] = fresnel_refraction(cos_i, e);
      AlbedoPair value;
      const double reflected_z = 2.0 * cos_i / s - wz;
      if (reflected_z > 0.0) value.reflectance = fresnel * outgoing_masking(smith_g1(reflected_z), false) * common;
      if (fresnel < 1.0) {
        const double transmitted_z = -wz / e + (cos_i / e - cos_t) / s;
        if (transmitted_z < 0.0) {
          value.transmittance = (1.0 - fresnel) * outgoing_masking(smith_g1(transmitted_z), true) * common;
        }
      }
      return value;
    };
    if (points.size() > uniform_count || !smooth_enough)
      return integrate_pieces<AlbedoPair>(points, rule_for, integrand);
    AlbedoPair sum;
    const QuadratureRule& hermite = rules.hermite();
    for (int k = 0; k < hermite.size(); ++k) sum += integrand(sigma * hermite.nodes[k]) * (sigma * hermite.weights[k]);
    return sum;
  };

  std::vector<Breakpoint> rows;
  uniform_breakpoints(0.0, rows);
  const std::size_t uniform_rows = rows.size();
  for (double radius : {1.0 / wz, e / wz})
    if (radius < range && radius <= 1.0 / wz) rows.push_back({radius, true});
  if (e < 1.0) {
    if (critical > sx) {
      const double cone_edge = e / std::sqrt(critical * critical - sx * sx);
      if (cone_edge < range) rows.push_back({cone_edge, true});
    }
    // Where the cone crosses the horizon circles, h ~ wi + k wo with wo = (cos phi, sin phi, 0) on the horizon and
    // q = k |sin phi| / wz: for refraction (k = e) wi.h = c means wo.h = 0, so sx cos phi = -e; for reflection
    // (k = 1) wi.h = sqrt((1 + wi.wo) / 2) = c gives sx cos phi = 2 c^2 - 1.
    for (const auto& [k, sx_cos_phi] : {std::pair{e, -e}, std::pair{1.0, 2.0 * critical * critical - 1.0}}) {
      if (std::abs(sx_cos_phi) >= sx) continue;
      const double cos_phi = sx_cos_phi / sx;
      const double crossing = k * std::sqrt(1.0 - cos_phi * cos_phi) / wz;
      if (crossing < range) rows.push_back({crossing, true});
    }
  }
  if (rows.size() > uniform_rows || !smooth_enough) {
    const auto rule_for = [&](double a, double b) { return rules(peak_density(a, b)); };
    return integrate_pieces<AlbedoPair>(rows, rule_for, row) * normalization;
  }
  AlbedoPair sum;  // the q > 0 half of a symmetric Gauss-Hermite rule
  const QuadratureRule& hermite = rules.hermite();
  for (int k = 0; k < hermite.size(); ++k)
    if (hermite.nodes[k] > 0.0) sum += row(sigma * hermite.nodes[k]) * (sigma * hermite.weights[k]);
  return sum * normalization;
}

}  // namespace

InterfaceAlbedo single_scattering_albedo(const RoughDielectric& interface, const Vec3& wi) {
  return single_scattering_albedo(interface, std::span<const Vec3>(&wi, 1)).front();
}

InterfaceAlbedo interface_albedo(const RoughDielectric& interface, const Vec3& wi) {
  return interface_albedo(interface, std::span<const Vec3>(&wi, 1)).front();
}

std::vector<InterfaceAlbedo> interface_albedo(const RoughDielectric& interface, std::span<const Vec3> wi) {
  return totals(interface_albedo_parts(interface, wi));
}

std::vector<InterfaceAlbedo> totals(std::span<const InterfaceAlbedoParts> parts) {
  std::vector<InterfaceAlbedo> result;
  result.reserve(parts.size());
  for (const InterfaceAlbedoParts& p : parts) result.push_back(p.total());
  return result;
}

std::vector<InterfaceAlbedoParts> interface_albedo_parts(const RoughDielectric& interface, std::span<const Vec3> wi,
                                                         const MultipleScatteringLobe* lobe) {
  std::vector<InterfaceAlbedoParts> parts;
  parts.reserve(wi.size());
  for (const InterfaceAlbedo& single : single_scattering_albedo(interface, wi)) parts.push_back({single, {0.0, 0.0}});
  if (!has_multiple_scattering(interface)) return parts;
  const std::optional<MultipleScatteringLobe> own =
      lobe ? std::nullopt : std::optional<MultipleScatteringLobe>(std::in_place, interface, 1);
  const MultipleScatteringLobe& shares = lobe ? *lobe : *own;
  for (std::size_t k = 0; k < wi.size(); ++k) {
    // Where single scattering keeps nearly all the light (small sigma, steep incidence) the rules' error can carry
    // R + T past 1; the interface then returns exactly all of it.
    InterfaceAlbedo& single = parts[k].single;
    const double kept = single.reflectance + single.transmittance;
    if (kept > 1.0) {
      single.reflectance /= kept;
      single.transmittance /= kept;
    }
    const double rest = std::max(0.0, single.loss());
    const double share = shares.transmitted_share(wi[k].z() > 0.0, std::abs(wi[k].z()));
    parts[k].multiple = {rest * (1.0 - share), rest * share};
  }
  return parts;
}

std::vector<InterfaceAlbedo> single_scattering_albedo(const RoughDielectric& interface, std::span<const Vec3> wi) {
  std::vector<InterfaceAlbedo> result;
  result.reserve(wi.size());
  if (interface.eta == 1.0) {
    result.assign(wi.size(), InterfaceAlbedo{0.0, 1.0});
    return result;
  }
  const PieceRules rules(interface.microfacet);
  const SmithG1Table smith_g1(interface.sigma);
  for (const Vec3& w : wi) {
    const double wz = std::abs(w.z());
    const double sx = std::hypot(w.x(), w.y());
    const double e = w.z() > 0.0 ? interface.eta : 1.0 / interface.eta;
    const double g1_in = smith_g1_beckmann(wz, interface.sigma);  // exact: once per direction
    if (wz == 0.0 || g1_in == 0.0) {
      result.push_back({0.0, 0.0});  // grazing: G1(wi) = 0
      continue;
    }
    const AlbedoPair pair = integrate_slopes(sx, wz, e, interface.sigma, g1_in, interface.microfacet, smith_g1, rules);
    result.push_back({pair.reflectance, pair.transmittance});
  }
  return result;
}

}  // namespace skinlayer
