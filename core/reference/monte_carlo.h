// An independent Monte Carlo reference for the skin layer: a random walk of photons through the same layer the
// solver models, written without any of the solver's machinery (no discrete ordinates, Fourier series, eigen-
// decompositions or tables). It shares only the Fresnel and Beckmann/Smith functions (core/interfaces/fresnel.h,
// core/interfaces/microfacet.h, which have their own unit tests), the microsurface random walk of core/reference
// (itself written from Fresnel and the Beckmann statistics alone), the Material type and its validation.
//
// Threads: this reference module uses std::thread, because a useful number of paths needs both cores; it is built
// as its own library (skinlayer_reference), so the solver library itself stays free of threads. Each thread owns its
// own std::mt19937_64 seeded from (seed, thread index), so a result is reproducible for the same seed and thread count.
//
// The walk (one photon = weight 1, unpolarized), for light from omega_i = (theta_i, phi_i = 0) onto the top:
//   * Rough interface crossing (top: eta = material.eta, sigma; bottom air: eta_b = bottom_eta(), sigma_b), with
//     w the direction back toward where the photon came from and n the macro normal on w's side:
//       - sample a microfacet normal h with density D(h) cos(alpha) (Beckmann slopes are Gaussian, variance
//         sigma^2/2 per axis); a sample with w.h <= 0 gets weight 0;
//       - weight *= |w.h| G1(w) / (|w.n| cos(alpha))   (expected value exactly 1: the Smith normalization);
//       - reflect about h with probability F(|w.h|, n_other/n_this), otherwise refract by Snell's law at h;
//       - weight *= G1(wo); a photon sent to the wrong side of the macro surface is lost.
//     This is an unbiased estimator of the energy transport of core's rough_dielectric_bsdf (Smith G1 on both
//     directions; what shadowing removes is lost): MicrofacetModel::Single, Stam 2001's interfaces. Under
//     MicrofacetModel::Multiple (the material's microfacet field) the photon instead walks on the microsurface
//     (core/reference/microsurface_walk.h, Heitz et al. 2016) until it leaves it, above or below, with weight 1:
//     nothing is lost. At eta = 1 the interface is absent and the photon passes straight through.
//   * Medium: free path s = -ln(u) in optical depth along the direction (the depth changes by s |cos|); at a
//     collision weight *= Omega (with Russian roulette for small weights) and the direction is resampled from the
//     Henyey-Greenstein phase function (analytic inversion, uniform azimuth about the current direction).
//     tau_b = +infinity (T = 0) is semi-infinite; tau_b = 0 (T = 1) has no medium.
//   * Stacks (Material::below): the depth runs through the layers, each with its own Omega and g. A free path that
//     reaches the face between two layers stops there (the exponential is memoryless, so the walk restarts at the
//     face): an index-matched face lets it pass; a rough interface between them (eta = n_below / n_above) is
//     crossed as above, from whichever side the photon arrives.
//   * Bottom: Air (a rough interface as above; transmitted photons leave below), Matched (photons reaching tau_b
//     leave unchanged), Lambert (at tau_b a cosine-distributed new upward direction, weight *= A).
//   * A path is cut after kMaxEventsPerPath events (collisions plus interface and base interactions); the rest of
//     its weight counts as absorbed. `truncated_paths` reports how often that happened.
//
// Tallies are by exit direction, in the graphics convention of core/conventions.h: theta_o from the normal of the
// exit side, phi = phi_o - phi_i in [0, 2 pi), phi = pi forward (mirror / straight through).
//
// Exit positions (RadialBin): the photon enters at the origin of the top face and its lateral position (x, y) moves
// by s (d_x, d_y) / mu_t for a free path of optical length s in a layer of extinction mu_t; crossings of interfaces
// and the Lambertian base happen at a point. Radii are in mm when every layer has its extinction (mu_t, 1/mm), and in
// mean free paths when a single layer has none (mu_t = 1). Light reflected before it entered (at r = 0) and the
// direct beam are in no annulus, as they are in no angular bin.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "core/material.h"

namespace skinlayer {

inline constexpr std::uint64_t kMaxEventsPerPath = 100000;

enum class ExitSide { Reflected, Transmitted };

// An angular bin on one exit side: theta in [theta_min, theta_max), phi in [phi_min, phi_max) (radians; phi is
// compared modulo 2 pi, so a range such as [-0.1, 0.1) around phi = 0 works).
struct AngularBin {
  ExitSide side = ExitSide::Reflected;
  double theta_min = 0.0;
  double theta_max = 0.0;
  double phi_min = 0.0;
  double phi_max = 0.0;
  // The bin's projected solid angle, int cos(theta) d omega = (phi_max - phi_min)(sin^2 theta_max - sin^2 theta_min)/2.
  double projected_solid_angle() const;
};

// An annulus of exit positions on one side: r in [r_min, r_max), in the result's length unit (mm, or mean free paths).
struct RadialBin {
  ExitSide side = ExitSide::Reflected;
  double r_min = 0.0;
  double r_max = 0.0;
  double area() const;  // pi (r_max^2 - r_min^2)
};

struct MonteCarloOptions {
  std::uint64_t paths = 100000;
  std::uint64_t seed = 1;
  int threads = 2;
  // A photon is dropped at its collision number max_scattering_order + 1 (0: never), so that the tallies hold the
  // light scattered at most that often (1: single scattering, a closed form's reference).
  std::uint64_t max_scattering_order = 0;
  // Called now and then from the calling thread with the number of paths finished so far (optional).
  std::function<void(std::uint64_t)> progress;
};

struct MonteCarloEstimate {
  double value = 0.0;
  double standard_error = 0.0;
};

struct MonteCarloResult {
  MonteCarloEstimate reflectance_surface;     // reflected at the first top interaction, never entered
  MonteCarloEstimate reflectance_subsurface;  // entered and later left through the top
  MonteCarloEstimate transmittance;           // left through the bottom, including the direct beam
  MonteCarloEstimate transmittance_direct;    // the unscattered, unrefracted beam (only with index-matched
                                              // boundaries on both sides); part of `transmittance`, not of any bin
  // Per caller bin: the BSDF averaged over the bin with projected-solid-angle weight, in 1/sr:
  //   (sum of exit weights in the bin) / (paths * projected_solid_angle).
  // Reflected bins contain surface and subsurface reflection.
  std::vector<MonteCarloEstimate> bins;
  // Per caller annulus: the light leaving through it per unit area and unit incident power,
  //   (sum of exit weights in the annulus) / (paths * area),   in 1/mm^2 (or 1/mfp^2, see lengths_in_mm).
  std::vector<MonteCarloEstimate> radial_bins;
  bool lengths_in_mm = false;  // radii in mm (every layer has mu_t); false: mean free paths of the single layer
  std::uint64_t paths = 0;
  std::uint64_t truncated_paths = 0;  // paths cut at kMaxEventsPerPath
};

// Traces options.paths photons incident at theta_i (radians, from +z, phi_i = 0). Throws ParameterError for an
// invalid material, theta_i outside [0, pi/2), an inverted bin or annulus, zero paths/threads, or annuli asked of a
// stack whose layers do not all have their extinction.
MonteCarloResult simulate_layer(const Material& material, double theta_i, std::span<const AngularBin> bins,
                                const MonteCarloOptions& options, std::span<const RadialBin> radial_bins = {});

}  // namespace skinlayer
