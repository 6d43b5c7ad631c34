// Monte Carlo reference: see monte_carlo.h. Nothing of the solver is used here.
#include "core/reference/monte_carlo.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <string>
#include <thread>

#include "core/conventions.h"
#include "core/interfaces/fresnel.h"
#include "core/interfaces/microfacet.h"
#include "core/reference/microsurface_walk.h"

namespace skinlayer {

double AngularBin::projected_solid_angle() const {
  const double s0 = std::sin(theta_min);
  const double s1 = std::sin(theta_max);
  return 0.5 * (phi_max - phi_min) * (s1 * s1 - s0 * s0);
}

double RadialBin::area() const { return kPi * (r_max * r_max - r_min * r_min); }

namespace {

using Rng = std::mt19937_64;

double uniform01(Rng& rng) {  // [0, 1)
  return std::generate_canonical<double, 53>(rng);
}

// Sum and sum of squares of per-photon contributions (each photon contributes at most once to each tally).
struct Moments {
  double sum = 0.0;
  double sum_sq = 0.0;
  void add(double x) {
    sum += x;
    sum_sq += x * x;
  }
  void merge(const Moments& other) {
    sum += other.sum;
    sum_sq += other.sum_sq;
  }
  MonteCarloEstimate estimate(double n, double scale = 1.0) const {
    const double mean = sum / n;
    const double variance = std::max(0.0, sum_sq / n - mean * mean);
    return {mean * scale, std::sqrt(variance / std::max(1.0, n - 1.0)) * scale};
  }
};

struct Tallies {
  Moments surface, subsurface, transmitted, direct;
  std::vector<Moments> bins, radial;
  std::uint64_t truncated = 0;
  void merge(const Tallies& other) {
    surface.merge(other.surface);
    subsurface.merge(other.subsurface);
    transmitted.merge(other.transmitted);
    direct.merge(other.direct);
    for (std::size_t b = 0; b < bins.size(); ++b) bins[b].merge(other.bins[b]);
    for (std::size_t b = 0; b < radial.size(); ++b) radial[b].merge(other.radial[b]);
    truncated += other.truncated;
  }
};

struct Crossing {
  bool alive = false;
  bool reflected = false;
  Vec3 wo;
  double weight = 0.0;
};

// One interaction with a rough dielectric interface, in a frame whose macro normal +z is on the incident side.
// w: unit direction toward where the photon came from (w.z > 0); eta_rel = n_other_side / n_this_side.
Crossing cross_rough_interface(const Vec3& w, double eta_rel, double sigma, MicrofacetModel model, Rng& rng) {
  if (model == MicrofacetModel::Multiple) {
    // Every meeting with the microsurface followed until the photon leaves it: nothing is lost, weight 1.
    const MicrosurfaceExit exit = MicrosurfaceWalk({eta_rel, sigma, model}).walk(w, rng);
    return {true, exit.direction.z() > 0.0, exit.direction, 1.0};
  }
  Crossing out;
  std::normal_distribution<double> slope(0.0, sigma / std::sqrt(2.0));
  const double sx = slope(rng);
  const double sy = slope(rng);
  const Vec3 h = Vec3(-sx, -sy, 1.0).normalized();  // density D(h) cos(alpha) d omega_h
  const double wh = w.dot(h);
  if (wh <= 0.0 || w.z() <= 0.0) return out;
  double weight = wh / (w.z() * h.z()) * smith_g1_beckmann(w.z(), sigma);
  const double fresnel = fresnel_dielectric(wh, eta_rel);
  if (uniform01(rng) < fresnel) {
    const Vec3 wo = 2.0 * wh * h - w;
    if (wo.z() <= 0.0) return out;
    out.reflected = true;
    out.wo = wo.normalized();
  } else {
    const double cos_t_sq = 1.0 - (1.0 - wh * wh) / (eta_rel * eta_rel);
    if (cos_t_sq <= 0.0) return out;  // total internal reflection has F = 1; never reached
    const Vec3 wo = -w / eta_rel + (wh / eta_rel - std::sqrt(cos_t_sq)) * h;
    if (wo.z() >= 0.0) return out;
    out.reflected = false;
    out.wo = wo.normalized();
  }
  weight *= smith_g1_beckmann(out.wo.z(), sigma);
  out.alive = weight > 0.0;
  out.weight = weight;
  return out;
}

Vec3 flip_z(const Vec3& v) { return {v.x(), v.y(), -v.z()}; }

// Henyey-Greenstein sample about the propagation direction d (analytic inversion of the cosine, uniform azimuth).
Vec3 sample_henyey_greenstein(const Vec3& d, double g, Rng& rng) {
  const double u = uniform01(rng);
  double cos_theta;
  if (std::abs(g) < 1e-6) {
    cos_theta = 2.0 * u - 1.0;
  } else {
    const double q = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
    cos_theta = (1.0 + g * g - q * q) / (2.0 * g);
  }
  cos_theta = std::clamp(cos_theta, -1.0, 1.0);
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const double phi = 2.0 * kPi * uniform01(rng);
  // Orthonormal basis (t, b, d).
  const Vec3 helper = std::abs(d.x()) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  const Vec3 t = d.cross(helper).normalized();
  const Vec3 b = d.cross(t);
  return (sin_theta * std::cos(phi) * t + sin_theta * std::sin(phi) * b + cos_theta * d).normalized();
}

Vec3 sample_cosine_upward(Rng& rng) {
  const double r = std::sqrt(uniform01(rng));
  const double phi = 2.0 * kPi * uniform01(rng);
  const double x = r * std::cos(phi);
  const double y = r * std::sin(phi);
  return {x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))};
}

bool phi_in_range(double phi, double lo, double hi) {
  for (double shift : {0.0, -2.0 * kPi, 2.0 * kPi}) {
    const double p = phi + shift;
    if (p >= lo && p < hi) return true;
  }
  return false;
}

// One slab of the stack in the walk's depth coordinate: optical depth from the top of the first layer.
struct WalkLayer {
  double top = 0.0, bottom = 0.0;  // bottom = +infinity for a semi-infinite last layer
  double albedo = 1.0, g = 0.0;
  double length = 1.0;  // lateral length per unit optical path: 1 / mu_t mm, or 1 (mean free paths)
  // The rough interface above the layer (none for the first, or eta = 1): eta = n_this / n_above.
  bool interface_above = false;
  double eta_above = 1.0, sigma_above = 0.5;
};

// Where the photon is on the top face's plane, in the result's length unit.
struct Lateral {
  double x = 0.0, y = 0.0;
  void move(const Vec3& d, double optical_path, double length) {
    x += d.x() * optical_path * length;
    y += d.y() * optical_path * length;
  }
  double radius() const { return std::hypot(x, y); }
};

class Walker {
 public:
  Walker(const Material& material, double theta_i, std::span<const AngularBin> bins, std::span<const RadialBin> radial,
         std::uint64_t max_order)
      : m_(material),
        bins_(bins),
        radial_(radial),
        max_order_(max_order),
        omega_i_(std::sin(theta_i), 0.0, std::cos(theta_i)) {
    top_present_ = material.eta != 1.0;
    eta_b_ = material.bottom_eta();
    sigma_b_ = material.bottom_sigma();
    double depth = 0.0;
    for (const StackedLayer& layer : stack_layers(material)) {
      WalkLayer walk{depth, depth + layer.tau, layer.albedo, layer.g, 1.0 / layer.extinction.value_or(1.0), false, 1.0,
                     0.5};
      if (layer.interface && layer.interface->eta != 1.0) {
        walk.interface_above = true;
        walk.eta_above = layer.interface->eta;
        walk.sigma_above = layer.interface->sigma;
      }
      layers_.push_back(walk);
      depth += layer.tau;
    }
    tau_b_ = depth;
  }

  void trace(Rng& rng, Tallies& tallies) const {
    double weight = 1.0;
    std::uint64_t collisions = 0;
    Lateral at;
    bool scattered = false;
    bool refracted = false;
    Vec3 d;
    if (top_present_) {
      const Crossing c = cross_rough_interface(omega_i_, m_.eta, m_.sigma, m_.microfacet, rng);
      if (!c.alive) return;
      weight *= c.weight;
      if (c.reflected) {
        tallies.surface.add(weight);
        tally_bins(tallies, ExitSide::Reflected, c.wo, weight);
        return;
      }
      refracted = true;
      d = c.wo;
    } else {
      d = -omega_i_;
    }
    double tau = 0.0;
    std::size_t layer = 0;  // the slab the photon is in
    for (std::uint64_t events = 0;; ++events) {
      if (events >= kMaxEventsPerPath) {
        ++tallies.truncated;
        return;
      }
      const double s = -std::log(1.0 - uniform01(rng));  // 1 - u in (0, 1]
      const double tau_new = tau - s * d.z();
      const WalkLayer& here = layers_[layer];
      if (d.z() < 0.0 && tau_new >= here.bottom && layer + 1 < layers_.size()) {
        // Reaches the next slab down. The free path is memoryless, so the walk restarts at the face.
        at.move(d, (here.bottom - tau) / -d.z(), here.length);
        tau = here.bottom;
        const WalkLayer& below = layers_[layer + 1];
        if (below.interface_above) {
          const Crossing c = cross_rough_interface(-d, below.eta_above, below.sigma_above, m_.microfacet, rng);
          if (!c.alive) return;
          weight *= c.weight;
          refracted = true;
          d = c.wo;
          if (c.reflected) continue;
        }
        ++layer;
      } else if (d.z() > 0.0 && tau_new <= here.top && layer > 0) {  // reaches the next slab up
        at.move(d, (tau - here.top) / d.z(), here.length);
        tau = here.top;
        if (here.interface_above) {
          const Crossing c =
              cross_rough_interface(flip_z(-d), 1.0 / here.eta_above, here.sigma_above, m_.microfacet, rng);
          if (!c.alive) return;
          weight *= c.weight;
          refracted = true;
          d = flip_z(c.wo);
          if (c.reflected) continue;
        }
        --layer;
      } else if (d.z() < 0.0 && tau_new >= tau_b_) {  // reaches the bottom
        at.move(d, (tau_b_ - tau) / -d.z(), here.length);
        tau = tau_b_;
        switch (m_.bottom.kind) {
          case BottomKind::Matched:
            exit_bottom(tallies, d, weight, !scattered && !refracted, at);
            return;
          case BottomKind::Air: {
            if (eta_b_ == 1.0) {
              exit_bottom(tallies, d, weight, !scattered && !refracted, at);
              return;
            }
            const Crossing c = cross_rough_interface(-d, 1.0 / eta_b_, sigma_b_, m_.microfacet, rng);
            if (!c.alive) return;
            weight *= c.weight;
            refracted = true;
            if (c.reflected) {
              d = c.wo;
              break;
            }
            exit_bottom(tallies, c.wo, weight, false, at);
            return;
          }
          case BottomKind::Lambert:
            weight *= m_.bottom.lambert_albedo;
            if (weight <= 0.0) return;
            scattered = true;
            d = sample_cosine_upward(rng);
            break;
        }
      } else if (d.z() > 0.0 && tau_new <= 0.0) {  // reaches the top from inside
        at.move(d, tau / d.z(), here.length);
        tau = 0.0;
        if (!top_present_) {
          exit_top(tallies, d, weight, at);
          return;
        }
        const Crossing c = cross_rough_interface(flip_z(-d), 1.0 / m_.eta, m_.sigma, m_.microfacet, rng);
        if (!c.alive) return;
        weight *= c.weight;
        const Vec3 wo = flip_z(c.wo);
        if (c.reflected) {
          d = wo;  // back down into the layer
        } else {
          exit_top(tallies, wo, weight, at);
          return;
        }
      } else {  // collision inside the medium
        at.move(d, s, here.length);
        tau = tau_new;
        if (max_order_ != 0 && ++collisions > max_order_) return;
        weight *= here.albedo;
        if (weight <= 0.0) return;
        if (weight < kRouletteThreshold) {
          if (uniform01(rng) >= kRouletteSurvival) return;
          weight /= kRouletteSurvival;
        }
        scattered = true;
        d = sample_henyey_greenstein(d, here.g, rng);
      }
    }
  }

 private:
  static constexpr double kRouletteThreshold = 0.05;
  static constexpr double kRouletteSurvival = 0.2;

  void exit_top(Tallies& tallies, const Vec3& wo, double weight, const Lateral& at) const {
    tallies.subsurface.add(weight);
    tally_bins(tallies, ExitSide::Reflected, wo, weight);
    tally_radial(tallies, ExitSide::Reflected, at, weight);
  }
  void exit_bottom(Tallies& tallies, const Vec3& wo, double weight, bool direct, const Lateral& at) const {
    tallies.transmitted.add(weight);
    if (direct) {
      tallies.direct.add(weight);
      return;  // a delta: belongs to no BTDF bin and no annulus
    }
    tally_bins(tallies, ExitSide::Transmitted, wo, weight);
    tally_radial(tallies, ExitSide::Transmitted, at, weight);
  }
  void tally_radial(Tallies& tallies, ExitSide side, const Lateral& at, double weight) const {
    if (radial_.empty()) return;
    const double r = at.radius();
    for (std::size_t b = 0; b < radial_.size(); ++b) {
      const RadialBin& bin = radial_[b];
      if (bin.side == side && r >= bin.r_min && r < bin.r_max) tallies.radial[b].add(weight);
    }
  }
  // wo points away from the surface on its exit side.
  void tally_bins(Tallies& tallies, ExitSide side, const Vec3& wo, double weight) const {
    if (bins_.empty()) return;
    const double cos_o = side == ExitSide::Reflected ? wo.z() : -wo.z();
    const double theta_o = std::acos(std::clamp(cos_o, -1.0, 1.0));
    double phi = std::atan2(wo.y(), wo.x());
    if (phi < 0.0) phi += 2.0 * kPi;
    for (std::size_t b = 0; b < bins_.size(); ++b) {
      const AngularBin& bin = bins_[b];
      if (bin.side != side || theta_o < bin.theta_min || theta_o >= bin.theta_max) continue;
      if (!phi_in_range(phi, bin.phi_min, bin.phi_max)) continue;
      tallies.bins[b].add(weight);
    }
  }

  const Material& m_;
  std::span<const AngularBin> bins_;
  std::span<const RadialBin> radial_;
  std::uint64_t max_order_ = 0;
  Vec3 omega_i_;
  bool top_present_ = true;
  double eta_b_ = 1.0;
  double sigma_b_ = 0.5;
  double tau_b_ = 0.0;  // the stack's total optical depth
  std::vector<WalkLayer> layers_;
};

}  // namespace

MonteCarloResult simulate_layer(const Material& material, double theta_i, std::span<const AngularBin> bins,
                                const MonteCarloOptions& options, std::span<const RadialBin> radial_bins) {
  validate(material);
  if (!(theta_i >= 0.0 && theta_i < 0.5 * kPi))
    throw ParameterError("theta_i = " + std::to_string(theta_i) + " is out of range; valid range is [0, pi/2)");
  if (options.paths == 0) throw ParameterError("Monte Carlo paths must be positive");
  if (options.threads < 1) throw ParameterError("Monte Carlo threads must be at least 1");
  for (const AngularBin& bin : bins) {
    if (!(bin.theta_min >= 0.0 && bin.theta_max > bin.theta_min && bin.theta_max <= 0.5 * kPi + 1e-12 &&
          bin.phi_max > bin.phi_min && bin.phi_max - bin.phi_min <= 2.0 * kPi + 1e-12))
      throw ParameterError("Monte Carlo angular bin is empty or out of range");
  }
  for (const RadialBin& bin : radial_bins) {
    if (!(bin.r_min >= 0.0 && bin.r_max > bin.r_min)) throw ParameterError("Monte Carlo annulus is empty or negative");
  }
  const std::vector<StackedLayer> layers = stack_layers(material);
  const auto with_length =
      std::ranges::count_if(layers, [](const StackedLayer& l) { return l.extinction.has_value(); });
  const bool lengths_in_mm = with_length == static_cast<std::ptrdiff_t>(layers.size());
  if (!radial_bins.empty() && !lengths_in_mm && layers.size() > 1) {
    throw ParameterError("exit positions of a stack need every layer's extinction mu_t (1/mm); " +
                         std::to_string(layers.size() - static_cast<std::size_t>(with_length)) + " of its " +
                         std::to_string(layers.size()) + " layers have none");
  }

  const Walker walker(material, theta_i, bins, radial_bins, options.max_scattering_order);
  const auto thread_count = static_cast<std::uint64_t>(options.threads);
  std::vector<Tallies> tallies(thread_count);
  for (Tallies& t : tallies) {
    t.bins.assign(bins.size(), Moments{});
    t.radial.assign(radial_bins.size(), Moments{});
  }
  std::atomic<std::uint64_t> done{0};
  constexpr std::uint64_t kChunk = 4096;

  auto work = [&](std::uint64_t index, bool report) {
    const std::uint64_t count = options.paths / thread_count + (index < options.paths % thread_count ? 1 : 0);
    std::seed_seq seq{static_cast<std::uint32_t>(options.seed), static_cast<std::uint32_t>(options.seed >> 32),
                      static_cast<std::uint32_t>(index), 0x5EEDu};
    Rng rng(seq);
    Tallies& t = tallies[index];
    for (std::uint64_t p = 0; p < count; ++p) {
      walker.trace(rng, t);
      if ((p + 1) % kChunk == 0) {
        const std::uint64_t total = done.fetch_add(kChunk) + kChunk;
        if (report && options.progress) options.progress(total);
      }
    }
    done.fetch_add(count % kChunk);
  };

  std::vector<std::thread> workers;
  for (std::uint64_t index = 1; index < thread_count; ++index) workers.emplace_back(work, index, false);
  work(0, true);  // the calling thread is worker 0 and reports progress
  for (std::thread& worker : workers) worker.join();
  if (options.progress) options.progress(done.load());

  Tallies total = std::move(tallies[0]);
  for (std::uint64_t index = 1; index < thread_count; ++index) total.merge(tallies[index]);

  const auto n = static_cast<double>(options.paths);
  MonteCarloResult result;
  result.paths = options.paths;
  result.truncated_paths = total.truncated;
  result.reflectance_surface = total.surface.estimate(n);
  result.reflectance_subsurface = total.subsurface.estimate(n);
  result.transmittance = total.transmitted.estimate(n);
  result.transmittance_direct = total.direct.estimate(n);
  result.bins.reserve(bins.size());
  for (std::size_t b = 0; b < bins.size(); ++b)
    result.bins.push_back(total.bins[b].estimate(n, 1.0 / bins[b].projected_solid_angle()));
  result.lengths_in_mm = lengths_in_mm;
  for (std::size_t b = 0; b < radial_bins.size(); ++b)
    result.radial_bins.push_back(total.radial[b].estimate(n, 1.0 / radial_bins[b].area()));
  return result;
}

}  // namespace skinlayer
