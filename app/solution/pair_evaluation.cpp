#include "app/solution/pair_evaluation.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/material.h"
#include "core/solve/solve_options.h"

namespace skinlayer {
namespace {

constexpr std::size_t kBlock = 4096;       // pairs per parallel-for index: a few ms of work, enough to hide its cost
constexpr std::size_t kPrefetchAhead = 8;  // pairs: ~2-4 us of work, more than a miss to memory

std::string entry(const char* name, std::size_t index, double value) {
  char text[96];
  std::snprintf(text, sizeof text, "%s[%zu] = %.17g", name, index, value);
  return text;
}

// The pairs' indices sorted by the table cell of (theta_i, theta_o), by counting sort: consecutive pairs then read
// the same few cache lines of the coefficient tables (megabytes for a colour material, far more than the caches),
// which for pairs in random order made the evaluation wait on memory. Every pair's value is computed exactly as in
// any other order; only the order changes. `grid` is the largest table's grid size: the unscattered lobe's table,
// where there is one, is the finer, and its cells fall inside those of the solver's tables.
std::vector<std::uint32_t> cell_order(int grid, std::span<const double> theta_i, std::span<const double> theta_o) {
  const auto cell = [grid](double degrees) {
    return std::min(static_cast<std::size_t>(LayerTables::grid_coordinate(degrees_to_radians(degrees), grid)),
                    static_cast<std::size_t>(grid - 1));
  };
  const std::size_t cells = static_cast<std::size_t>(grid) * grid;
  std::vector<std::uint32_t> key(theta_i.size());
  std::vector<std::size_t> start(cells + 1, 0);
  for (std::size_t k = 0; k < theta_i.size(); ++k) {
    key[k] = static_cast<std::uint32_t>(cell(theta_i[k]) * grid + cell(theta_o[k]));
    ++start[key[k] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
  std::vector<std::uint32_t> order(theta_i.size());
  for (std::size_t k = 0; k < theta_i.size(); ++k) order[start[key[k]]++] = static_cast<std::uint32_t>(k);
  return order;
}

}  // namespace

int value_channels(const SolvedDocument& solved) { return solved.grey ? 1 : 3; }

std::optional<UnscatteredLobe> parse_unscattered_lobe(std::string_view text) {
  if (text == "auto") return UnscatteredLobe::Auto;
  if (text == "exact") return UnscatteredLobe::Exact;
  if (text == "table") return UnscatteredLobe::Table;
  return std::nullopt;
}

namespace {

// Whether `lobe` asks for the lobe tables at `count` pairs; ParameterError where Table cannot be had.
bool wants_lobe_tables(const SolvedDocument& solved, std::size_t count, UnscatteredLobe lobe) {
  if (lobe == UnscatteredLobe::Exact || (lobe == UnscatteredLobe::Auto && count < kTabulatedFromPairs)) return false;
  if (lobe == UnscatteredLobe::Table) {
    for (const LayerTables& tables : solved.tables) {
      const UnscatteredLight& light = tables.unscattered();
      if (light.path() != UnscatteredPath::TopThenBottom || TabulatedTwoInterfaceBtdf::can_tabulate(light)) continue;
      char text[200];
      std::snprintf(text, sizeof text,
                    "unscattered = table needs sigma >= %g at both rough interfaces the unscattered light crosses; "
                    "one has sigma = %.10g (use auto or exact)",
                    kMinTabulatedSigma, std::min(light.top().sigma, light.bottom().sigma));
      throw ParameterError(text);
    }
  }
  return true;
}

}  // namespace

void check_direction_pairs(std::span<const double> theta_i, std::span<const double> theta_o,
                           std::span<const double> phi) {
  if (theta_o.size() != theta_i.size() || phi.size() != theta_i.size()) {
    throw ParameterError("theta_i, theta_o and phi must have the same length (" + std::to_string(theta_i.size()) +
                         ", " + std::to_string(theta_o.size()) + ", " + std::to_string(phi.size()) + ")");
  }
  for (std::size_t k = 0; k < theta_i.size(); ++k) {
    for (const auto& [name, values] : {std::pair{"theta_i", theta_i}, std::pair{"theta_o", theta_o}}) {
      if (!(values[k] >= 0.0 && values[k] <= 90.0)) {
        throw ParameterError(entry(name, k, values[k]) + " is out of range; valid range is [0, 90] (degrees)");
      }
    }
    if (!std::isfinite(phi[k])) {
      throw ParameterError(entry("phi", k, phi[k]) + " is not finite; phi may be any finite number (degrees)");
    }
  }
}

const std::vector<TabulatedTwoInterfaceBtdf>& UnscatteredLobeCache::lobes(const SolvedDocument& solved,
                                                                          const ParallelFor& parallel_for) {
  std::call_once(built_, [&] { lobes_ = tabulate_unscattered(solved, parallel_for); });
  return lobes_;
}

void evaluate_pairs(const SolvedDocument& solved, std::span<const double> theta_i, std::span<const double> theta_o,
                    std::span<const double> phi, const BsdfArrays& out, const ParallelFor& parallel_for,
                    const std::function<bool()>& cancelled, UnscatteredLobe lobe, UnscatteredLobeCache* cache) {
  check_direction_pairs(theta_i, theta_o, phi);
  if (theta_i.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw ParameterError("at most " + std::to_string(std::numeric_limits<std::uint32_t>::max()) +
                         " direction pairs at once; got " + std::to_string(theta_i.size()));
  }
  const std::size_t count = theta_i.size();
  const auto channels = static_cast<std::size_t>(value_channels(solved));
  if (out.surface.size() != count || out.subsurface.size() != count * channels || out.brdf.size() != count * channels ||
      out.btdf.size() != count * channels) {
    throw std::invalid_argument("evaluate_pairs: the output arrays do not fit the pairs");
  }
  std::vector<TabulatedTwoInterfaceBtdf> own;
  std::span<const TabulatedTwoInterfaceBtdf> lobes;
  if (wants_lobe_tables(solved, count, lobe)) {
    if (cache == nullptr) own = tabulate_unscattered(solved, parallel_for);
    lobes = cache != nullptr ? std::span(cache->lobes(solved, parallel_for)) : std::span(own);
    if (cancelled && cancelled()) throw SolveCancelled();
  }
  const std::vector<std::uint32_t> order =
      cell_order(lobes.empty() ? solved.tables.front().grid_size() : lobes.front().grid_size(), theta_i, theta_o);
  std::atomic<bool> stopped = false;
  const auto blocks = static_cast<int>((count + kBlock - 1) / kBlock);
  run_parallel(parallel_for, blocks, [&](int block) {
    if (stopped.load() || (cancelled && cancelled())) {
      stopped = true;
      return;
    }
    const std::size_t begin = static_cast<std::size_t>(block) * kBlock, end = std::min(count, begin + kBlock);
    for (std::size_t n = begin; n < end; ++n) {
      // In cell order the pairs' own entries are scattered over the arrays: ask for those a few pairs ahead now,
      // so that their cache misses overlap this pair's work instead of stalling it.
      if (n + kPrefetchAhead < end) {
        const std::size_t ahead = order[n + kPrefetchAhead];
        for (const double* entry : {&theta_i[ahead], &theta_o[ahead], &phi[ahead]}) __builtin_prefetch(entry);
        __builtin_prefetch(&out.surface[ahead], 1);
        for (const std::span<double>& values : {out.subsurface, out.brdf, out.btdf}) {
          __builtin_prefetch(&values[ahead * channels], 1);
        }
      }
      const std::size_t k = order[n];
      const BsdfPoint point = evaluate(solved, degrees_to_radians(theta_i[k]), degrees_to_radians(theta_o[k]),
                                       degrees_to_radians(phi[k]), lobes);
      out.surface[k] = point.surface;
      for (std::size_t c = 0; c < channels; ++c) {
        out.subsurface[k * channels + c] = point.subsurface[c];
        out.brdf[k * channels + c] = point.surface + point.subsurface[c];
        out.btdf[k * channels + c] = point.btdf[c];
      }
    }
  });
  if (stopped.load()) throw SolveCancelled();
}

std::vector<Eigen::Array3d> brdf_rgb(const SolvedDocument& solved, std::span<const Vec3> light,
                                     std::span<const Vec3> view, const ParallelFor& parallel_for) {
  const std::size_t n = light.size(), width = static_cast<std::size_t>(value_channels(solved));
  std::vector<double> theta_i(n), theta_o(n), phi(n);
  for (std::size_t k = 0; k < n; ++k) {
    theta_i[k] = radians_to_degrees(std::acos(std::min(1.0, light[k].z())));
    theta_o[k] = radians_to_degrees(std::acos(std::min(1.0, view[k].z())));
    phi[k] = radians_to_degrees(std::atan2(view[k].y(), view[k].x()) - std::atan2(light[k].y(), light[k].x()));
  }
  std::vector<double> surface(n), subsurface(n * width), brdf(n * width), btdf(n * width);
  evaluate_pairs(solved, theta_i, theta_o, phi, {surface, subsurface, brdf, btdf}, parallel_for);
  std::vector<Eigen::Array3d> values(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t c = 0; c < 3; ++c)
      values[k](static_cast<Eigen::Index>(c)) = brdf[k * width + (width == 1 ? 0 : c)];
  }
  return values;
}

}  // namespace skinlayer
