// One validation set run: the solver against the Monte Carlo reference (core/reference/monte_carlo.h) for the
// directional albedos (surface and subsurface reflectance, transmittance) and the BSDF averaged over angular bins in
// the plane of incidence (back, phi = 0, and forward, phi = 180 degrees) and across it (phi = 90 degrees).
//
// Agreement: |MC - solver| <= 4 MC standard errors, nothing else added. A bin is judged only when it holds enough
// paths for its standard error to mean something: the solver expects >= 25 exits in it, or the Monte Carlo estimate
// has a relative standard error <= 20% (either side can open the judgement, so a solver that predicts nothing
// where light leaves is still caught). Other bins are reported as sparse.
//
// The solver's side of a bin is its BSDF averaged with the same projected-solid-angle weight the Monte Carlo tally
// uses (cos theta domega), by a 16 x 16 midpoint rule over the bin. Reflected bins hold surface plus subsurface
// reflection; transmitted bins hold the scattered light (the unscattered beam of an index-matched layer is a delta
// direction that no bin of finite size resolves; it is in the transmittance).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/validate/validation_grid.h"
#include "core/reference/monte_carlo.h"
#include "core/series/layer_tables.h"

namespace skinlayer::validation {

inline constexpr double kAgreementSigmas = 4.0;

enum class Verdict { Agrees, Disagrees, Sparse };

// Where a bin lies: phi = 0 (back toward the light), phi = 180 degrees (forward) or phi = 90 degrees (across).
enum class BinPlane { Back, Forward, Across };

struct ValidationBin {
  ExitSide side = ExitSide::Reflected;
  BinPlane plane = BinPlane::Back;
  double theta_min_deg = 0.0;
  double theta_max_deg = 0.0;
  double phi_half_width = 0.25;  // radians about the plane's azimuth
  const char* peak = nullptr;    // a peak bin: "mirror", "straight through" or "normal"; null for a band
};

// The bins of a set lit at theta_i_deg: theta bands of 15 degrees from 0 to 90, +-0.25 rad of azimuth about each
// plane, on the reflected side and, when the layer transmits, on the transmitted side; and peak bins that can see a
// lobe a bin of 15 degrees averages away: about 2 degrees either way (4 degrees in theta, 4 degrees of arc in
// azimuth; the normal's is the cone theta < 2 degrees) at the mirror direction, the flat interfaces' straight-through
// direction and the normal on each side.
std::vector<ValidationBin> validation_bins(const Material& material, double theta_i_deg);
AngularBin angular_bin(const ValidationBin& bin);

struct Comparison {
  std::string quantity;  // e.g. "R subsurface", "BRDF φ 180° θo [30,45)"
  double monte_carlo = 0.0;
  double standard_error = 0.0;
  double solver = 0.0;
  Verdict verdict = Verdict::Agrees;

  double difference() const { return monte_carlo - solver; }
  // In standard errors (0 when both sides are exactly equal; infinite when the MC error is 0 and they differ).
  double sigmas() const;
  double relative() const;  // difference / solver (0 when the solver's value is 0)
};

struct SetResult {
  ValidationSet set;
  std::uint64_t paths = 0;
  std::uint64_t truncated_paths = 0;
  double monte_carlo_seconds = 0.0;
  double solver_seconds = 0.0;
  std::vector<Comparison> albedos;  // R surface, R subsurface, T
  std::vector<ValidationBin> bins;
  std::vector<Comparison> bin_comparisons;  // one per bin, in the same order
  LayerTables tables;                       // the solver's tables, for plotting

  bool agrees() const;  // no comparison disagrees
  // The largest |sigmas()| and |relative()| over the judged comparisons.
  double worst_sigmas() const;
  double worst_relative() const;
};

struct RunOptions {
  std::uint64_t paths = 0;  // Monte Carlo paths
  std::uint64_t seed = 1;
  int threads = 2;
  std::function<void(std::uint64_t)> progress;  // paths traced so far (optional)
};

// The solver's BSDF over a bin, averaged as the Monte Carlo tallies it (see above), in 1/sr.
double solver_bin_average(const Material& material, const LayerTables& tables, double theta_i,
                          const ValidationBin& bin);

// Runs the set: the solver, then the Monte Carlo walk, and compares them.
SetResult run_validation_set(const ValidationSet& set, const RunOptions& options);

// The verdict on one comparison, from the rules above; expected_counts < 0 for an albedo (always judged).
Verdict judge(double monte_carlo, double standard_error, double solver, double expected_counts);

}  // namespace skinlayer::validation
