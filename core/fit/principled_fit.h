// The Principled BSDF (core/targets/principled_bsdf.h) that best reproduces a reflectance (docs/model.md §22.2): the
// first half of `skinlayer fit --target principled` (issue 44), on samples the caller takes from its BRDF.
//
// The metric: the cosine-weighted BRDF, f cos(theta_i), on a fixed set of direction pairs (principled_fit_pairs):
// light from 0 to 80 degrees in steps of 10, the view on a Gauss-Legendre grid of the hemisphere, each pair weighted
// by its quadrature weight, so that the sum of squares is the integral over the view's hemisphere of the squared
// difference, summed over the light's angles. That is the error in the light a surface sends to each direction,
// which is what a picture shows. The directional albedo at normal incidence is matched exactly: per channel the base
// colour enters the albedo linearly, A = a C + b, and is solved for at every step, so the least squares choose the
// rest (roughness, specular, sheen, clearcoat and its roughness) within the node's ranges. Where the colour would
// leave [0, 1] (the other lobes alone reflect more than the target), what the albedo then misses joins the
// residuals, heavily weighted, so that the fit moves back to where it can match.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/targets/principled_bsdf.h"

namespace skinlayer {

struct DirectionPair {
  Vec3 omega_i, omega_o;  // toward the light and toward the viewer, graphics convention
  double weight = 0.0;    // the quadrature weight of the view (sr)
};

// The fixed pairs, for each light at 0, 10, ..., 80 degrees (azimuth 0): the view on `polar` Gauss-Legendre cosines
// times 2 x `polar` azimuths over the hemisphere; and again on `polar` x 2 `polar` nodes in a cap of
// kMirrorCapDegrees about the mirror direction, crowded toward it, where a sharp surface lobe is (views below the
// horizon left out). The cap is counted on top of the hemisphere: its error weighs twice.
constexpr double kMirrorCapDegrees = 30.0;
std::vector<DirectionPair> principled_fit_pairs(int polar = 12);

// The least roughness (and clearcoat roughness) the fit gives: GGX alpha 0.01, a lobe about a degree wide, which the
// cap's nodes still resolve. No preset's interface is sharper (Beckmann sigma 0.08 is about roughness 0.28).
constexpr double kMinFittedRoughness = 0.1;

struct PrincipledFitTarget {
  std::vector<DirectionPair> pairs;   // principled_fit_pairs()
  std::vector<Rgb> brdf_cosine;       // the target's f cos(theta_i) on each pair
  std::vector<double> albedo_angles;  // light angles (radians) of the directional albedos below; the first is 0
  std::vector<Rgb> albedo;            // the target's directional albedo at each
};

struct PrincipledFit {
  PrincipledParameters parameters;
  bool albedo_matched = true;  // false where a channel's colour had to be clamped to [0, 1]
  Rgb albedo_miss = Rgb::Zero();  // the fitted albedo at normal incidence less the target's (0 where matched)
  // The errors, per channel: of the lobe, RMS and worst over the pairs relative to the target's largest value there
  // (so that near-zero values do not blow up the ratio); of the albedo over albedo_angles, RMS and worst relative.
  Rgb lobe_rms = Rgb::Zero(), lobe_worst = Rgb::Zero(), albedo_rms = Rgb::Zero(), albedo_worst = Rgb::Zero();
};

// Throws std::invalid_argument for a target whose sizes disagree or whose first albedo angle is not 0.
PrincipledFit fit_principled(const PrincipledFitTarget& target);

}  // namespace skinlayer
