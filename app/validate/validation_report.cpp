#include "app/validate/validation_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "app/material/material_flag_text.h"

namespace skinlayer::validation {
namespace {

constexpr std::size_t kWorstBinsPrinted = 3;

std::string formatted(const char* format, auto... values) {
  char text[256];
  std::snprintf(text, sizeof text, format, values...);
  return text;
}

std::string sigmas_text(const Comparison& c) {
  const double z = c.sigmas();
  return std::isinf(z) ? (z > 0 ? "+inf" : "-inf") : formatted("%+.2f", z);
}

const char* verdict_text(Verdict verdict) {
  switch (verdict) {
    case Verdict::Agrees: return "ok";
    case Verdict::Disagrees: return "DISAGREES";
    case Verdict::Sparse: return "sparse";
  }
  return "";
}

std::string row_text(const Comparison& c) {
  return formatted("  %-26s %11.5g ± %-10.3g %11.5g %9s %+9.3f%%  %s\n", c.quantity.c_str(), c.monte_carlo,
                   c.standard_error, c.solver, sigmas_text(c).c_str(), 100.0 * c.relative(), verdict_text(c.verdict));
}

std::size_t count(const SetResult& r, Verdict verdict) {
  const auto is = [verdict](const Comparison& c) { return c.verdict == verdict; };
  return static_cast<std::size_t>(std::count_if(r.albedos.begin(), r.albedos.end(), is) +
                                  std::count_if(r.bin_comparisons.begin(), r.bin_comparisons.end(), is));
}

std::string verdict_line(const SetResult& r) {
  const std::size_t judged = r.albedos.size() + r.bin_comparisons.size() - count(r, Verdict::Sparse);
  return formatted("%s: %zu of %zu comparisons judged (%zu sparse bins), %zu disagree; worst %.2f SE, %.2f%%",
                   r.agrees() ? "agrees" : "DISAGREES", judged, r.albedos.size() + r.bin_comparisons.size(),
                   count(r, Verdict::Sparse), count(r, Verdict::Disagrees), r.worst_sigmas(),
                   100.0 * r.worst_relative());
}

// How many judged comparisons a correct solver would still see beyond 4 standard errors, by chance alone.
std::string chance_line(std::span<const SetResult> results) {
  constexpr double kTwoSidedTailBeyond4 = 6.334e-5;  // P(|Z| > 4) for a standard normal Z
  std::size_t judged = 0;
  for (const SetResult& r : results) judged += r.albedos.size() + r.bin_comparisons.size() - count(r, Verdict::Sparse);
  return formatted("(%zu comparisons judged; a correct solver would see about %.2f of them beyond 4 SE by chance)",
                   judged, kTwoSidedTailBeyond4 * static_cast<double>(judged));
}

std::string markdown_row(const Comparison& c) {
  return formatted("| %s | %.6g | %.3g | %.6g | %s | %+.3f%% | %s |\n", c.quantity.c_str(), c.monte_carlo,
                   c.standard_error, c.solver, sigmas_text(c).c_str(), 100.0 * c.relative(),
                   c.verdict == Verdict::Disagrees ? "**disagrees**" : verdict_text(c.verdict));
}

}  // namespace

void print_set_table(std::ostream& out, const SetResult& r) {
  out << formatted("  %-26s %24s %11s %9s %10s\n", "quantity", "Monte Carlo ± SE", "solver", "diff/SE", "relative");
  for (const Comparison& c : r.albedos) out << row_text(c);
  std::vector<const Comparison*> bins;
  for (const Comparison& c : r.bin_comparisons) {
    if (c.verdict != Verdict::Sparse) bins.push_back(&c);
  }
  std::sort(bins.begin(), bins.end(), [](const Comparison* a, const Comparison* b) {
    return std::abs(a->sigmas()) > std::abs(b->sigmas());
  });
  const std::size_t shown = std::min(bins.size(), kWorstBinsPrinted);
  if (shown > 0) out << formatted("  worst %zu of %zu judged bins:\n", shown, bins.size());
  for (std::size_t k = 0; k < shown; ++k) out << row_text(*bins[k]);
  out << "  " << verdict_line(r) << formatted("  [MC %.1f s, solver %.2f s]\n", r.monte_carlo_seconds,
                                              r.solver_seconds);
}

void print_summary(std::ostream& out, std::span<const SetResult> results) {
  out << formatted("%-22s %6s %10s %10s %10s %10s %9s %10s\n", "set", "θi", "paths", "R_s/SE", "R_sub/SE", "T/SE",
                   "worst/SE", "worst rel");
  std::size_t agreeing = 0;
  for (const SetResult& r : results) {
    agreeing += r.agrees() ? 1 : 0;
    out << formatted("%-22s %5.0f° %10llu %10s %10s %10s %9.2f %9.2f%%  %s\n", r.set.name.c_str(), r.set.theta_i_deg,
                     static_cast<unsigned long long>(r.paths), sigmas_text(r.albedos[0]).c_str(),
                     sigmas_text(r.albedos[1]).c_str(), sigmas_text(r.albedos[2]).c_str(), r.worst_sigmas(),
                     100.0 * r.worst_relative(), r.agrees() ? "agrees" : "DISAGREES");
  }
  out << formatted("%zu of %zu sets agree within %.0f standard errors\n", agreeing, results.size(), kAgreementSigmas);
  out << chance_line(results) << '\n';
}

void write_markdown_report(const std::filesystem::path& dir, std::span<const SetResult> results,
                           const RunDescription& run) {
  const std::filesystem::path path = dir / "validation.md";
  std::ofstream file(path);
  if (!file) throw std::runtime_error("cannot write " + path.string());
  std::size_t agreeing = 0;
  for (const SetResult& r : results) agreeing += r.agrees() ? 1 : 0;

  file << "# Solver against Monte Carlo\n\n";
  file << formatted("Written by `skinlayer validate%s` (seed %llu, %d threads, %.0f s). %zu of %zu sets agree.\n\n",
                    run.mode == "quick" ? " --quick" : "", static_cast<unsigned long long>(run.seed), run.threads,
                    run.seconds, agreeing, results.size());
  file << "Each set compares the solver with an independent Monte Carlo random walk through the same layer "
          "(`core/reference/monte_carlo.h`): the directional albedos (surface and subsurface reflectance, "
          "transmittance) and the BSDF averaged over bins of 15° in θo and ±0.25 rad in φ, in the plane of "
          "incidence (φ 0° back, φ 180° forward) and across it (φ 90°). A comparison agrees when "
          "|MC − solver| ≤ 4 MC standard errors, with no other allowance. A bin is judged when the solver expects "
          "≥ 25 exits in it or the MC estimate's relative standard error is ≤ 20%; other bins are *sparse* and only "
          "reported. Reflected bins hold surface plus subsurface reflection; transmitted bins hold scattered light "
          "(an index-matched layer's unscattered beam is in T only). Plots: the solver's BSDF as curves, its bin "
          "averages as bars, the MC bins as points with ±2 SE. Ω = 1 with T = 0 is left out: the mean length of a "
          "random walk in a conservative half-space diverges.\n\n";

  file << chance_line(results) << "\n\n";
  file << "| set | θi | paths | R surface (SE) | R subsurface (SE) | T (SE) | worst (SE) | worst (rel.) | verdict |\n"
          "|---|---|---|---|---|---|---|---|---|\n";
  for (const SetResult& r : results) {
    file << formatted("| [%s](#%s) | %g° | %llu | %s | %s | %s | %.2f | %.2f%% | %s |\n", r.set.name.c_str(),
                      r.set.name.c_str(), r.set.theta_i_deg, static_cast<unsigned long long>(r.paths),
                      sigmas_text(r.albedos[0]).c_str(), sigmas_text(r.albedos[1]).c_str(),
                      sigmas_text(r.albedos[2]).c_str(), r.worst_sigmas(), 100.0 * r.worst_relative(),
                      r.agrees() ? "agrees" : "**disagrees**");
  }
  for (const SetResult& r : results) {
    file << "\n## " << r.set.name << "\n\n" << r.set.description << formatted(", lit at θi %g°. ", r.set.theta_i_deg)
         << formatted("%llu paths (%llu cut at the event limit), MC %.1f s, solver %.3f s.\n\n",
                      static_cast<unsigned long long>(r.paths), static_cast<unsigned long long>(r.truncated_paths),
                      r.monte_carlo_seconds, r.solver_seconds)
         << "Material: `" << material_to_flags(r.set.material) << "`\n\n"
         << "![" << r.set.name << "](" << r.set.name << ".png)\n\n"
         << verdict_line(r) << ".\n\n"
         << "| quantity | Monte Carlo | SE | solver | diff / SE | relative | verdict |\n"
            "|---|---|---|---|---|---|---|\n";
    for (const Comparison& c : r.albedos) file << markdown_row(c);
    for (const Comparison& c : r.bin_comparisons) file << markdown_row(c);
  }
  if (!file.flush()) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace skinlayer::validation
