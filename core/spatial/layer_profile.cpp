// docs/model.md §21.7, §21.10 and §21.14: single scattering in closed form, the rest through k-space.
#include "core/spatial/layer_profile.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unsupported/Eigen/SpecialFunctions>
#include <unsupported/Eigen/Splines>

#include "core/conventions.h"
#include "core/interfaces/layer_interfaces.h"
#include "core/material.h"
#include "core/series/quadrature.h"
#include "core/spatial/entering_radiance.h"
#include "core/spatial/lateral_bottom_face.h"
#include "core/spatial/lateral_internal_face.h"
#include "core/spatial/lateral_top_interface.h"
#include "core/spatial/rough_top_single_scattering.h"
#include "core/spatial/single_scattering_profile.h"
#include "core/spatial/transmitted_low_orders.h"
#include "core/spatial/unscattered_images.h"

namespace skinlayer {
namespace {

// R_ms (or T_ms) on the grid s_i = i h, k = k_s sinh(s): the C2 cubic B-spline through the samples and their
// mirror images at -s_i (R_ms is even in k, so its derivative in s vanishes at 0), 0 beyond the last sample.
class FrequencySpline {
 public:
  FrequencySpline(const std::vector<double>& values, double step, double scale)
      : count_(static_cast<int>(values.size())), step_(step), scale_(scale) {
    const int n = 2 * count_ - 1;
    Eigen::RowVectorXd points(n), parameters(n);
    for (int j = 0; j < n; ++j) {
      const int i = j - (count_ - 1);
      points(j) = values[static_cast<std::size_t>(std::abs(i))];
      parameters(j) = 0.5 + 0.5 * i / (count_ - 1.0);  // s / s_max mapped onto [0, 1]
    }
    spline_ = Eigen::SplineFitting<Spline>::Interpolate(points, 3, parameters);
  }
  double operator()(double k) const {
    const double s = std::asinh(k / scale_) / step_;
    if (s >= count_ - 1) return 0.0;
    // A cosine roll-off over the upper half of the frequencies, so that the transform ends smoothly (§21.7).
    const double k_max = max_frequency();
    const double taper = k < 0.5 * k_max ? 1.0 : 0.5 * (1.0 + std::cos(kPi * (2.0 * k / k_max - 1.0)));
    return taper * spline_(0.5 + 0.5 * s / (count_ - 1.0))(0);
  }
  double max_frequency() const { return node(count_ - 1); }
  // The sample frequencies k_i, i = 0 .. samples() - 1: the spline's joins.
  int samples() const { return count_; }
  double node(int i) const { return scale_ * std::sinh(step_ * i); }

 private:
  using Spline = Eigen::Spline<double, 1, 3>;
  int count_;
  double step_, scale_;
  Spline spline_;
};

// int_0^kmax F(k) kernel(k) dk by 8-point Gauss-Legendre panels: within each cell of the spline (so that no panel
// straddles its C1 joins), at most `width` wide. Level L has width 0.25 / 2^L; a Bessel kernel of largest radius r
// takes the first level no wider than its period, 2 pi / r (eight nodes a period; against half a period the skin's
// point values move by 5e-8 relative). The nodes and F's weighted values are shared by every
// radius of a level, so the spline is evaluated once per node, not once per node and radius.
class FrequencyQuadrature {
 public:
  FrequencyQuadrature(const FrequencySpline& F, double largest_radius) {
    const QuadratureRule unit = gauss_legendre(8, 0.0, 1.0);
    for (int level = 0; level <= level_for(largest_radius); ++level) {
      const double width = 0.25 / std::ldexp(1.0, level);
      Level nodes;
      for (int cell = 0; cell + 1 < F.samples(); ++cell) {
        const double from = F.node(cell), to = F.node(cell + 1);
        const int panels = std::max(1, static_cast<int>(std::ceil((to - from) / width)));
        const double length = (to - from) / panels;
        for (int p = 0; p < panels; ++p) {
          for (std::size_t g = 0; g < unit.nodes.size(); ++g) {
            const double k = from + length * (p + unit.nodes[g]);
            nodes.k.push_back(k);
            nodes.weighted.push_back(length * unit.weights[g] * F(k));
          }
        }
      }
      levels_.push_back(std::move(nodes));
    }
  }
  // int_0^kmax F(k) kernel(k) dk, on the level that a kernel of largest radius r needs.
  template <class Kernel>
  double integrate(double r, const Kernel& kernel) const {
    const Level& nodes = levels_[std::min(static_cast<std::size_t>(level_for(r)), levels_.size() - 1)];
    double total = 0.0;
    for (std::size_t i = 0; i < nodes.k.size(); ++i) total += nodes.weighted[i] * kernel(nodes.k[i]);
    return total;
  }

 private:
  struct Level {
    std::vector<double> k, weighted;
  };
  static int level_for(double r) {
    return r * 0.25 <= 2.0 * kPi ? 0 : static_cast<int>(std::ceil(std::log2(r * 0.25 / (2.0 * kPi))));
  }
  std::vector<Level> levels_;
};

// int_0^kmax F(k) [r1 J1(k r1) - r0 J1(k r0)] dk: the power through the annulus [r0, r1).
double annulus_power(const FrequencyQuadrature& F, double r0, double r1) {
  return F.integrate(r1, [&](double k) {
    return r1 * Eigen::numext::bessel_j1(k * r1) - (r0 > 0.0 ? r0 * Eigen::numext::bessel_j1(k * r0) : 0.0);
  });
}

// (1 / 2 pi) int_0^kmax F(k) J0(k r) k dk: the inverse Hankel transform at one radius.
double point_value(const FrequencyQuadrature& F, double r) {
  return F.integrate(r, [&](double k) { return Eigen::numext::bessel_j0(k * r) * k; }) / (2.0 * kPi);
}

void check_options(const LayerProfileOptions& options) {
  if (options.frequencies < 4 || !(options.max_frequency > 0.0) || !(options.frequency_scale > 0.0)) {
    throw std::invalid_argument("layer_profile: needs >= 4 frequencies and positive frequency bounds");
  }
}

// The layer as the solves see it: its slabs, and how the light enters them. A collimated beam into one open slab over
// a matched half-space is the beam of §21.4 with its exact single scattering (§21.6); light that enters as node
// radiance (through a rough top, or diffuse), and a collimated beam into a stack or through smooth faces, have their
// operators built once, at the options' resolution (§21.9, §21.12, §21.14).
struct SolvedLayer {
  SolvedLayer(const ProfileLayer& described, const LayerProfileOptions& chosen)
      : layer(described), slabs(described.slabs()), options(chosen) {
    check_options(options);
    const int N = options.resolution.ordinates, M = options.resolution.azimuth_modes;
    const bool finite = std::isfinite(slabs.back().tau);
    if (layer.top && layer.smooth_top) throw std::invalid_argument("layer_profile: a top is rough or smooth, not both");
    const int bottoms = int(layer.smooth_bottom.has_value()) + int(layer.rough_bottom.has_value()) +
                        int(layer.lambert_bottom.has_value());
    if (bottoms > 1) throw std::invalid_argument("layer_profile: a stack has one bottom face");
    if (bottoms > 0 && !finite) throw std::invalid_argument("layer_profile: a half-space has no bottom face");
    if (layer.smooth_top && layer.incidence == Incidence::Diffuse) {
      throw std::invalid_argument("layer_profile: diffuse light through a smooth top is not computed yet");
    }
    entry = entry_interface(layer, N, M, options.interface_azimuths);
    bottom = bottom_face(layer, N, M, options.interface_azimuths);
    if (layer.smooth_bottom) exit = smooth_exit_fraction(*layer.smooth_bottom);
    if (layer.rough_bottom) exit = rough_exit_fraction(*layer.rough_bottom);
    if (layer.lambert_bottom) exit = [](double) { return 0.0; };
    // Light that enters as node radiance crosses a finite stack unscattered at every angle; a smooth bottom would send
    // it back up as rings that the profile does not take apart yet.
    if (entry && !entry->source.isZero() && layer.smooth_bottom) {
      throw ParameterError(
          "profile: a smooth bottom face is taken so far under an open or smooth top at normal incidence, not under a "
          "rough top or in diffuse light");
    }
    // A collimated beam would meet a rough or diffuse bottom at the entry point and leave it spread over directions.
    if ((layer.rough_bottom || layer.lambert_bottom) && (!entry || entry->collimated > 0.0)) {
      throw ParameterError(
          "profile: a rough bottom or a Lambertian base is taken so far where the light enters spread over "
          "directions: under a rough top, or in diffuse light");
    }
    if (entry && finite) entering = EnteringRadiance(*entry, layer.top, N);
    take_faces(finite);
    if (bottom && entry && !entry->source.isZero()) {
      if (!faces.empty()) {
        throw ParameterError(
            "profile: a rough bottom or a Lambertian base under a stack with interfaces between its layers is not "
            "computed yet");
      }
      images = UnscatteredImages(layer, slabs, *entry, *bottom, options);
    }
  }
  // The interfaces between slabs (§21.16), their operators built once; `upper` ends at the first of them.
  void take_faces(bool finite) {
    if (!layer.faces.empty() && layer.faces.size() != layer.below.size()) {
      throw std::invalid_argument("layer_profile: faces needs one entry per slab below the first");
    }
    upper = slabs;
    for (std::size_t l = 0; l < layer.faces.size(); ++l) {
      if (!layer.faces[l]) continue;
      if (!entry || entry->collimated > 0.0) {
        throw ParameterError(
            "profile: interfaces between layers are taken so far where the light enters spread over directions: "
            "under a rough top, or in diffuse light");
      }
      if (finite && !options.reflectance_only) {
        throw ParameterError(
            "profile: the light through an interface between layers and out of the bottom is not computed yet; the "
            "stack must end in a half-space (tau inf)");
      }
      if (faces.empty()) {
        faces.resize(slabs.size());
        upper.assign(slabs.begin(), slabs.begin() + static_cast<std::ptrdiff_t>(l) + 1);
      }
      faces[l + 1] = lateral_internal_face(*layer.faces[l], options.resolution.ordinates,
                                           options.resolution.azimuth_modes, options.interface_azimuths);
    }
  }
  // The modes that frequency k needs: the k.s term couples mode m to m + 1 with strength k sin(theta) / 2, so at
  // low k the high modes carry nothing (§21.7).
  LateralFrequencyResolution resolution_at(double k) const {
    if (!options.adaptive_modes) return options.resolution;
    double sparsest = slabs.front().relative_extinction;
    for (const LateralSlab& slab : slabs) sparsest = std::min(sparsest, slab.relative_extinction);
    const int needed = 4 + static_cast<int>(std::ceil(8.0 * std::sqrt(k / sparsest)));
    return {options.resolution.ordinates, std::min(options.resolution.azimuth_modes, needed)};
  }
  LateralFrequencyResponse response(double k) const {
    return lateral_stack_response(slabs, entry ? &*entry : nullptr, k, resolution_at(k), bottom ? &*bottom : nullptr,
                                  faces);
  }
  // The discrete ordinates' own low orders at k: R_1, and T_1 plus the unscattered node radiance T_0 (§21.15).
  LateralFrequencyResponse single_scattering(double k) const {
    if (!entry) return collimated_single_scattering_response(slabs, nullptr, k, resolution_at(k));
    // Light entering as node radiance, in closed form per pair of eigenvalues; a collimated beam through the solve
    // without scattering. Neither face sends light back: what it does is multiple scattering's part.
    LateralFrequencyResponse orders;
    if (!entry->source.isZero()) {
      // Above the first interface between slabs: what is scattered once below it crossed that interface, is no longer
      // singular at the beam (it leaves from at least the interface's depth), and stays in the k-space part.
      const RoughTopLowOrders node =
          rough_top_low_orders(upper, *entry, k, resolution_at(k), bottom ? bottom->exit : Eigen::VectorXd());
      orders.reflectance = node.reflected_once;
      orders.transmittance = node.transmitted_once + node.transmitted_unscattered;
    }
    if (entry->collimated > 0.0) {
      const LateralFrequencyResponse beam =
          collimated_single_scattering_response(slabs, &*entry, k, resolution_at(k), bottom ? &*bottom : nullptr);
      orders.reflectance += beam.reflectance;
      orders.transmittance += beam.transmittance;
    }
    return orders;
  }
  // The low orders' power through the annulus [r0, r1) of a face, and their density at r > 0, in closed form: single
  // scattering on the top; on a finite stack's bottom the unscattered light too, continuous in angle (§21.15).
  double single_scattered_power(LayerFace face, double r0, double r1) const {
    if (!entry) return skinlayer::single_scattered_power(layer.tau, layer.albedo, layer.g, face, r0, r1);
    if (face == LayerFace::Top) {
      return rough_top_single_scattered_power(upper, *entry, options.resolution.ordinates, r0, r1);
    }
    return unscattered_transmitted_power(slabs, *entering, exit, r0, r1) +
           single_scattered_transmitted_power(slabs, *entering, exit, r0, r1);
  }
  double single_scattered_density(LayerFace face, double r) const {
    if (!entry) return skinlayer::single_scattered_density(layer.tau, layer.albedo, layer.g, face, r);
    if (face == LayerFace::Top)
      return rough_top_single_scattered_density(upper, *entry, options.resolution.ordinates, r);
    return unscattered_transmitted_density(slabs, *entering, exit, r) +
           single_scattered_transmitted_density(slabs, *entering, exit, r);
  }

  ProfileLayer layer;
  std::vector<LateralSlab> slabs;
  LayerProfileOptions options;
  std::optional<LateralTopInterface> entry;  // none: the collimated beam into one open slab (§21.4)
  std::optional<LateralBottomFace> bottom;   // a bottom face under a finite stack
  UnscatteredImages images;                  // the unscattered bounce's finer image (§21.17)
  ExitFraction exit;                         // its exit fraction, continuous in angle (empty: none, all leaves)
  std::optional<EnteringRadiance> entering;  // the entry's light, continuous in angle, under a finite stack
  std::vector<std::optional<LateralInternalFace>> faces;  // per slab, the interface above it; empty: none
  std::vector<LateralSlab> upper;  // the slabs above the first interface between slabs (all of them without one)
};

// The multiply scattered light's transforms, sampled and splined (§21.7), with the totals at k = 0.
struct MultipleScatteringTransforms {
  FrequencySpline reflected, transmitted;
  double total_reflectance = 0.0, total_transmittance = 0.0;
};

MultipleScatteringTransforms multiple_scattering_transforms(const SolvedLayer& solved) {
  const LayerProfileOptions& options = solved.options;
  const double step = std::asinh(options.max_frequency / options.frequency_scale) / (options.frequencies - 1);
  std::vector<double> reflected(static_cast<std::size_t>(options.frequencies));
  std::vector<double> transmitted(reflected.size());
  std::vector<LateralFrequencyResponse> all(reflected.size());
  run_parallel(options.parallel_for, options.frequencies, [&](int i) {
    const double k = options.frequency_scale * std::sinh(step * i);
    const std::size_t at = static_cast<std::size_t>(i);
    all[at] = solved.response(k);
    const LateralFrequencyResponse once = solved.single_scattering(k);
    reflected[at] = all[at].reflectance - once.reflectance +
                    solved.images.reflectance_correction(k, solved.resolution_at(k).azimuth_modes);
    transmitted[at] = all[at].transmittance - once.transmittance;
  });
  return {FrequencySpline(reflected, step, options.frequency_scale),
          FrequencySpline(transmitted, step, options.frequency_scale), all.front().reflectance,
          all.front().transmittance};
}

// The totals, then value(solved, face, transform, i) at each of `count` places (annuli or radii) out to
// largest_radius, on both faces, the places side by side through the caller's parallel-for.
template <class Value>
LayerProfile assemble_profile(const ProfileLayer& layer, const LayerProfileOptions& options, std::size_t count,
                              double largest_radius, const Value& value) {
  const SolvedLayer solved(layer, options);
  const MultipleScatteringTransforms ms = multiple_scattering_transforms(solved);
  const bool transmits = !options.reflectance_only && std::isfinite(solved.slabs.back().tau);
  const FrequencyQuadrature reflected(ms.reflected, largest_radius);
  const std::optional<FrequencyQuadrature> transmitted =
      transmits ? std::optional(FrequencyQuadrature(ms.transmitted, largest_radius)) : std::nullopt;
  LayerProfile profile;
  profile.total_reflectance = ms.total_reflectance;
  profile.total_transmittance = ms.total_transmittance;
  profile.reflectance.resize(count);
  if (!options.reflectance_only) profile.transmittance.assign(count, 0.0);
  run_parallel(options.parallel_for, static_cast<int>(count), [&](int place) {
    const std::size_t i = static_cast<std::size_t>(place);
    profile.reflectance[i] = value(solved, LayerFace::Top, reflected, i);
    if (transmits) profile.transmittance[i] = value(solved, LayerFace::Bottom, *transmitted, i);
  });
  return profile;
}

}  // namespace

std::optional<LateralTopInterface> entry_interface(const ProfileLayer& layer, int ordinates, int modes, int azimuths) {
  if (layer.top) return lateral_top_interface(*layer.top, ordinates, modes, layer.incidence, azimuths);
  if (layer.smooth_top) return smooth_top_interface(*layer.smooth_top, ordinates, modes);
  // No top, through the rough top's path: all but the classic open slab's beam.
  if (layer.incidence == Incidence::Diffuse || !layer.below.empty() || layer.smooth_bottom || layer.rough_bottom ||
      layer.lambert_bottom) {
    return open_top_interface(ordinates, modes, layer.incidence);
  }
  return std::nullopt;
}

std::optional<LateralBottomFace> bottom_face(const ProfileLayer& layer, int ordinates, int modes, int azimuths) {
  if (layer.smooth_bottom) return smooth_bottom_face(*layer.smooth_bottom, ordinates, modes);
  if (layer.rough_bottom) return rough_bottom_face(*layer.rough_bottom, ordinates, modes, azimuths);
  if (layer.lambert_bottom) return lambert_bottom_face(*layer.lambert_bottom, ordinates, modes);
  return std::nullopt;
}

ProfileLayer profile_layer(const Material& m, Incidence incidence) {
  ProfileLayer layer{m.tau, m.albedo, m.g};
  layer.incidence = incidence;
  if (m.eta != 1.0) layer.top = top_interface(m);
  for (const StackedLayer& below : m.below) {
    if (!m.extinction || !below.extinction) {
      throw std::invalid_argument("profile_layer: a stack's layers need their extinction (mu_t) to relate lengths");
    }
    layer.below.push_back({below.tau, below.albedo, below.g, *below.extinction / *m.extinction});
    const bool face = below.interface && below.interface->eta != 1.0;
    layer.faces.push_back(
        face ? std::optional(RoughDielectric{below.interface->eta, below.interface->sigma, m.microfacet})
             : std::nullopt);
  }
  if (std::isfinite(m.total_tau())) {
    if (m.bottom.kind == BottomKind::Lambert) layer.lambert_bottom = m.bottom.lambert_albedo;
    if (m.bottom.kind == BottomKind::Air && m.bottom_eta() != 1.0) layer.rough_bottom = bottom_interface(m);
  }
  return layer;
}

std::vector<LateralSlab> ProfileLayer::slabs() const {
  std::vector<LateralSlab> all = {{tau, albedo, g, 1.0}};
  all.insert(all.end(), below.begin(), below.end());
  return all;
}

LayerProfile layer_profile(const ProfileLayer& layer, std::span<const double> edges,
                           const LayerProfileOptions& options) {
  if (edges.size() < 2 || !(edges.front() >= 0.0) || !std::isfinite(edges.back()) ||
      !std::is_sorted(edges.begin(), edges.end()) || std::adjacent_find(edges.begin(), edges.end()) != edges.end()) {
    throw ParameterError("profile: the annuli's edges must be at least two finite, increasing radii from 0 or more");
  }
  return assemble_profile(
      layer, options, edges.size() - 1, edges.back(),
      [&](const SolvedLayer& solved, LayerFace face, const FrequencyQuadrature& transform, std::size_t a) {
        const double r0 = edges[a], r1 = edges[a + 1];
        return (solved.single_scattered_power(face, r0, r1) + annulus_power(transform, r0, r1)) /
               (kPi * (r1 * r1 - r0 * r0));
      });
}

LayerProfile layer_profile_at(const ProfileLayer& layer, std::span<const double> radii,
                              const LayerProfileOptions& options) {
  if (radii.empty() || !std::all_of(radii.begin(), radii.end(), [](double r) { return r > 0.0 && std::isfinite(r); })) {
    throw ParameterError("profile: radii must be finite and > 0 (the profile is infinite at the beam)");
  }
  return assemble_profile(
      layer, options, radii.size(), *std::max_element(radii.begin(), radii.end()),
      [&](const SolvedLayer& solved, LayerFace face, const FrequencyQuadrature& transform, std::size_t i) {
        return solved.single_scattered_density(face, radii[i]) + point_value(transform, radii[i]);
      });
}

}  // namespace skinlayer
