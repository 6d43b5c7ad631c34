// A solved document evaluated over many direction pairs at once (the Python module's Solution.eval, which takes
// numpy arrays of a million pairs): the pairs are checked, then split into blocks that run through the caller's
// parallel-for, each pair through evaluate() (solved_document.h), so every value is the one `skinlayer eval` writes.
//
// Angles are degrees, as eval reads them: theta_i and theta_o in [0, 90] from the normal of their side, phi the
// outgoing minus the incident azimuth (180 = forward), any finite number. Values are BSDFs in 1/sr.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "app/solution/solved_document.h"
#include "core/parallel_for.h"

namespace skinlayer {

// The channels a document's values have: 1 for a grey document, 3 (red, green, blue) otherwise.
int value_channels(const SolvedDocument& solved);

// Throws ParameterError for the first pair out of range, naming the array and the index:
// "theta_o[12] = 95 is out of range; valid range is [0, 90] (degrees)"; also for arrays of unequal length.
void check_direction_pairs(std::span<const double> theta_i, std::span<const double> theta_o,
                           std::span<const double> phi);

// Where the values go: n = theta_i.size() entries of surface, n x value_channels entries (pair-major) of the others.
struct BsdfArrays {
  std::span<double> surface;     // brdf_surface: no albedo in it, one value per pair
  std::span<double> subsurface;  // brdf_subsurface
  std::span<double> brdf;        // brdf_surface + brdf_subsurface
  std::span<double> btdf;        // btdf, without the unscattered beam
};

// How the unscattered lobe through two rough interfaces is evaluated (the other paths have closed forms; see
// core/unscattered/unscattered_light.h): exact, by its pointwise quadrature (~100-200 us a pair); table, from
// TabulatedTwoInterfaceBtdf (~0.1 s to build, then < 1 us a pair, within 0.5% of the lobe's peak; both interfaces'
// sigma >= 0.15); auto, the table from kTabulatedFromPairs pairs on where it can be built, else exact.
enum class UnscatteredLobe { Auto, Exact, Table };
inline constexpr std::size_t kTabulatedFromPairs = 4096;
// "auto", "exact", "table"; empty for anything else.
std::optional<UnscatteredLobe> parse_unscattered_lobe(std::string_view text);
// The choices as eval's --unscattered and Solution.eval's `unscattered` describe them, for their errors.
inline constexpr std::string_view kUnscatteredLobeChoices =
    "auto (a table from 4096 pairs on), exact (pointwise), table (sigma >= 0.15)";

// The lobe tables of one solved document (tabulate_unscattered), built the first time an evaluation asks for them and
// kept for the next ones (the Python module's Solution holds one). Safe to share between threads.
class UnscatteredLobeCache {
 public:
  const std::vector<TabulatedTwoInterfaceBtdf>& lobes(const SolvedDocument& solved, const ParallelFor& parallel_for);

 private:
  std::once_flag built_;
  std::vector<TabulatedTwoInterfaceBtdf> lobes_;
};

// Fills `out` for every pair (checked first), in the order of the pairs' table cells (for the memory caches; the
// values do not depend on it). At most 2^32 - 1 pairs at once. Asks `cancelled` between blocks: when it returns
// true the remaining blocks are skipped and SolveCancelled is thrown. `lobe` Table throws ParameterError for a
// two-interface lobe that cannot be tabulated (a sigma below 0.15). The tables come from `cache` when one is given
// (it must be this document's), else are built for this call.
void evaluate_pairs(const SolvedDocument& solved, std::span<const double> theta_i, std::span<const double> theta_o,
                    std::span<const double> phi, const BsdfArrays& out, const ParallelFor& parallel_for,
                    const std::function<bool()>& cancelled = {}, UnscatteredLobe lobe = UnscatteredLobe::Auto,
                    UnscatteredLobeCache* cache = nullptr);

// The BRDF (surface + subsurface, 1/sr) in red, green and blue at pairs given as unit vectors in the surface's frame
// (graphics convention; the light's and the view's, both above the surface), through evaluate_pairs: what the shader
// fits and their pictures compare with.
std::vector<Eigen::Array3d> brdf_rgb(const SolvedDocument& solved, std::span<const Vec3> light,
                                     std::span<const Vec3> view, const ParallelFor& parallel_for);

}  // namespace skinlayer
