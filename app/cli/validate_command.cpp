#include "app/cli/validate_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>
#include <vector>

#include "app/cli/errors.h"
#include "app/cli/flag_parser.h"
#include "app/cli/material_flags.h"
#include "app/figures/font.h"
#include "app/material/picture_metadata.h"
#include "app/text/numbers.h"
#include "app/text/quoted.h"
#include "app/validate/validation_grid.h"
#include "app/validate/validation_plot.h"
#include "app/validate/validation_report.h"
#include "app/validate/validation_run.h"

namespace skinlayer::cli {
namespace {

constexpr double kProgressInterval = 2.0;  // seconds between progress lines within one set

// A whole number in [lo, hi] from a flag's text, or UsageError naming the flag and the range.
std::uint64_t whole_number(std::string_view flag, std::string_view text, double lo, double hi) {
  const std::optional<double> value = text::parse_number(text);
  if (!value || !(*value >= lo && *value <= hi) || *value != std::floor(*value)) {
    throw UsageError(std::string(flag) + " = " + text::quoted(text) + " must be a whole number in [" +
                     text::format_short(lo) + ", " + text::format_short(hi) + "]");
  }
  return static_cast<std::uint64_t>(*value);
}

// The sets named by --set (a comma-separated list of set names), in grid order; every set without the flag.
std::vector<validation::ValidationSet> chosen_sets(std::optional<std::string_view> names) {
  std::vector<validation::ValidationSet> grid = validation::validation_grid();
  if (!names) return grid;
  std::vector<std::string_view> wanted;
  for (std::string_view rest = *names; !rest.empty();) {
    const std::size_t comma = rest.find(',');
    wanted.push_back(rest.substr(0, comma));
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
  }
  std::string known;
  for (const validation::ValidationSet& s : grid) known += (known.empty() ? "" : ", ") + s.name;
  for (const std::string_view name : wanted) {
    const bool found =
        std::any_of(grid.begin(), grid.end(), [name](const validation::ValidationSet& s) { return s.name == name; });
    if (!found) throw UsageError("set = " + text::quoted(name) + " is not a validation set; the sets are " + known);
  }
  std::erase_if(grid, [&wanted](const validation::ValidationSet& s) {
    return std::find(wanted.begin(), wanted.end(), s.name) == wanted.end();
  });
  return grid;
}

std::string with_thousands(std::uint64_t n) {
  const std::string digits = std::to_string(n);
  std::string grouped;
  for (std::size_t k = 0; k < digits.size(); ++k) {
    if (k > 0 && (digits.size() - k) % 3 == 0) grouped += ',';
    grouped += digits[k];
  }
  return grouped;
}

}  // namespace

std::string validate_usage() {
  return "Usage: skinlayer validate [--quick] [-o DIR] [--set NAMES] [--seed N] [--threads N] [--microfacet M]\n"
         "\n"
         "Checks the solver against an independent Monte Carlo random walk through the same layer, over a grid of\n"
         "parameter sets (the paper's figure settings; g 0, 0.5, 0.9; Ω 0.5, 0.99, 1; σ 0.1, 0.5, 1; η 1, 1.2, 1.4, "
         "2;\n"
         "thin and semi-infinite layers; air, matched and Lambertian bottoms). For each set it compares the\n"
         "directional albedos and the BSDF in angular bins in and across the plane of incidence, and prints the\n"
         "differences in Monte Carlo standard errors and in relative terms. A set agrees when every judged\n"
         "comparison is within 4 standard errors. Writes DIR/validation.md and one DIR/<set>.png per set.\n"
         "  --quick            a tenth of the paths (what CI runs; about a minute on 2 cores)\n"
         "  -o, --output DIR   the report's folder (created if missing; default validation)\n"
         "  --set NAMES        only these sets, comma-separated (default: all)\n"
         "  --seed N           Monte Carlo seed of the grid's first set; set k of the grid uses N + k (default 1)\n"
         "  --threads N        Monte Carlo threads, a whole number in [1, 256] (default: the cores)\n"
         "  --microfacet M     the interfaces of every set, multiple or single (default multiple). Under multiple\n"
         "                     the photons walk on the microsurface, and the solver's interfaces keep the light\n"
         "                     that meets it more than once; single is Stam 2001's model, where that light is lost.\n"
         "Exit status: 0 when every set agrees, 1 when any set disagrees.\n";
}

int run_validate_command(std::span<const std::string_view> arguments, std::ostream& out) {
  const std::vector<std::string_view> known = {"output", "set", "seed", "threads", "microfacet"};
  const std::vector<std::string_view> switches = {"quick"};
  const ParsedFlags flags = ParsedFlags::parse(arguments, known, "skinlayer validate", switches);
  const bool quick = flags.has("quick");
  const std::uint64_t seed = flags.has("seed") ? whole_number("seed", *flags.value("seed"), 0, 1e15) : 1;
  const int threads = flags.has("threads") ? static_cast<int>(whole_number("threads", *flags.value("threads"), 1, 256))
                                           : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<validation::ValidationSet> sets = chosen_sets(flags.value("set"));
  if (const auto text = flags.value("microfacet")) {
    const MicrofacetModel model = microfacet_from_text(*text);
    for (validation::ValidationSet& set : sets) set.material.microfacet = model;
  }
  const std::filesystem::path dir{std::string(flags.value("output").value_or("validation"))};
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) {
    throw std::runtime_error("cannot create the folder " + dir.string() + ": " +
                             (error ? error.message() : std::string("a file of that name exists")));
  }

  const figures::Font font;
  std::vector<validation::SetResult> results;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const validation::ValidationSet& set = sets[k];
    validation::RunOptions options;
    options.paths = quick ? set.quick_paths : set.paths;
    options.seed = seed + set.grid_index;  // a set's seed does not depend on which other sets run
    options.threads = threads;
    auto last_report = std::chrono::steady_clock::now();
    options.progress = [&](std::uint64_t done) {
      const auto now = std::chrono::steady_clock::now();
      if (done >= options.paths || std::chrono::duration<double>(now - last_report).count() < kProgressInterval) {
        return;
      }
      last_report = now;
      out << "    " << with_thousands(done) << " of " << with_thousands(options.paths) << " paths traced\n"
          << std::flush;
    };
    char header[256];
    std::snprintf(header, sizeof header, "[%zu/%zu] %s: %s, θi %g°, %s paths\n", k + 1, sets.size(), set.name.c_str(),
                  set.description.c_str(), set.theta_i_deg, with_thousands(options.paths).c_str());
    out << header << std::flush;
    results.push_back(validation::run_validation_set(set, options));
    validation::print_set_table(out, results.back());
    MaterialDocument material = grey_document(set.material);  // the plot remembers the set's material
    material.name = set.name;
    material.description = set.description;
    const nlohmann::ordered_json settings = {
        {"command", "validate"}, {"set", set.name}, {"light_theta", set.theta_i_deg}};
    write_png(validation::draw_validation_plot(results.back(), font), (dir / (set.name + ".png")).string(),
              {picture_metadata(material, settings)});
    results.back().tables = LayerTables();  // drawn; the summary needs only the comparisons
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << '\n';
  validation::print_summary(out, results);
  validation::write_markdown_report(dir, results, {quick ? "quick" : "full", seed, threads, seconds});
  char footer[320];
  std::snprintf(footer, sizeof footer, "wrote %s and %zu plots in %.1f s\n", (dir / "validation.md").string().c_str(),
                results.size(), seconds);
  out << footer;
  const bool all_agree =
      std::all_of(results.begin(), results.end(), [](const validation::SetResult& r) { return r.agrees(); });
  return all_agree ? kExitSuccess : kExitFailure;
}

}  // namespace skinlayer::cli
