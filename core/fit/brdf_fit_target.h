// What a shader fit reproduces and how its error is told (docs/model.md §22.2): samples of a BRDF on a fixed set of
// direction pairs and its directional albedo at a few angles, and the errors of any BRDF against them. The Principled
// fit (principled_fit.h) and the OpenPBR fit (openpbr_fit.h) share them, so that their errors compare.
//
// The metric: the cosine-weighted BRDF, f cos(theta_i), on the pairs of fit_pairs: light from 0 to 80 degrees in
// steps of 10, the view on a Gauss-Legendre grid of the hemisphere, each pair weighted by its quadrature weight, so
// that the sum of squares is the integral over the view's hemisphere of the squared difference, summed over the
// light's angles. That is the error in the light a surface sends to each direction, which is what a picture shows.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <span>
#include <vector>

#include "core/fit/bounded_least_squares.h"
#include "core/interfaces/microfacet.h"

namespace skinlayer {

using Rgb = Eigen::Array3d;

struct DirectionPair {
  Vec3 omega_i, omega_o;  // toward the light and toward the viewer, graphics convention
  double weight = 0.0;    // the quadrature weight of the view (sr)
};

// The fixed pairs, for each light at 0, 10, ..., 80 degrees (azimuth 0): the view on `polar` Gauss-Legendre cosines
// times 2 x `polar` azimuths over the hemisphere; and again on `polar` x 2 `polar` nodes in a cap of
// kMirrorCapDegrees about the mirror direction, crowded toward it, where a sharp surface lobe is (views below the
// horizon left out). The cap is counted on top of the hemisphere: its error weighs twice.
constexpr double kMirrorCapDegrees = 30.0;
std::vector<DirectionPair> fit_pairs(int polar = 12);

// The least roughness a fit gives: GGX alpha 0.01, a lobe about a degree wide, which the cap's nodes still resolve.
// No preset's interface is sharper (Beckmann sigma 0.08 is about roughness 0.28).
constexpr double kMinFittedRoughness = 0.1;

// The weight of a fit's albedo miss among its residuals: large enough that the fit leaves a region where the colour
// cannot match the albedo at normal incidence (against lobe residuals of about sqrt(weight) f cos, ~0.1 each).
constexpr double kAlbedoMissWeight = 30.0;

struct BrdfFitTarget {
  std::vector<DirectionPair> pairs;   // fit_pairs()
  std::vector<Rgb> brdf_cosine;       // the target's f cos(theta_i) on each pair
  std::vector<double> albedo_angles;  // angles (radians) of the directional albedos below; the first is 0
  std::vector<Rgb> albedo;            // the target's directional albedo at each
};

// Throws std::invalid_argument for a target whose sizes disagree or whose first albedo angle is not 0.
void check_fit_target(const BrdfFitTarget& target);

// The errors of a fitted BRDF, per channel: of the lobe, RMS and worst over the pairs relative to the target's
// largest value there (so that near-zero values do not blow up the ratio); of the albedo over albedo_angles, RMS and
// worst relative.
struct FitErrors {
  Rgb lobe_rms = Rgb::Zero(), lobe_worst = Rgb::Zero(), albedo_rms = Rgb::Zero(), albedo_worst = Rgb::Zero();
  // The directional albedos behind albedo_rms and albedo_worst, at the target's albedo_angles (radians): the fitted
  // shader's (what its renderer shows under a white sky) and the target's.
  std::vector<double> albedo_angles;
  std::vector<Rgb> albedo_fitted, albedo_target;
};

// `brdf_cosine(omega_i, omega_o)` is the fitted f cos(theta_i); `albedo(theta)` its directional albedo with the light
// (or, for a shader that is not reciprocal, the view) at theta from the normal.
FitErrors fit_errors(const BrdfFitTarget& target, const std::function<Rgb(const Vec3&, const Vec3&)>& brdf_cosine,
                     const std::function<Rgb(double theta)>& albedo);

// A shader at one vector of its fit's parameters, its colour already solved for the albedo at normal incidence: its
// f cos(theta_i), and what that albedo misses where no colour in [0, 1] matches it (0 elsewhere).
struct FittedShape {
  std::function<Rgb(const Vec3&, const Vec3&)> brdf_cosine;
  Rgb albedo_miss = Rgb::Zero();
};

// The diffuse colour in [0, 1] whose albedo at normal incidence, `albedo(color)` (rising in each channel), is
// `target`: by bisection per channel, 0 or 1 where the range holds no such colour, and then what the albedo misses in
// `miss` (0 where matched). For a shader whose albedo is not linear in its colour (an Oren-Nayar or EON diffuse).
Rgb color_for_albedo(const std::function<Rgb(const Rgb&)>& albedo, const Rgb& target, Rgb& miss);

// The least squares both shader fits solve (bounded_least_squares.h): for each pair sqrt(weight) times the fitted
// f cos less the target's, per channel, then the albedo's miss times kAlbedoMissWeight. Started from each of `starts`
// (the least squares find the nearest minimum), keeping the fit with the smaller residual.
BoundedFit fit_shape(const BrdfFitTarget& target, const std::function<FittedShape(const Eigen::VectorXd&)>& shape,
                     std::span<const Eigen::VectorXd> starts, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi);

}  // namespace skinlayer
